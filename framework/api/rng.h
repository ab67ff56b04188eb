#pragma once
#include "vec_math.h"

#include <cstdint>

enum class Sampler; // the framework's choice of numbers (framework/render/sampler.h)

// A random number generator for one pixel sample (or, constructed directly, a plain PCG32 stream:
// 64-bit LCG state, XSH-RR output).
//
// Renders are deterministic: each pixel sample gets its own generator, seeded from
// (render seed, pixel index, sample index) by `RNG::for_sample`, so the image does not depend on
// the number of threads or the order of tiles.
class RNG {
public:
	explicit RNG(uint64_t seed = 0, uint64_t stream = 0);

	// The generator for one pixel sample.
	static RNG for_sample(uint64_t render_seed, uint64_t pixel_index, uint64_t sample_index);

	uint32_t integer();            // uniform in [0, 2^32)
	uint32_t integer(uint32_t n);  // uniform in [0, n), n > 0, without modulo bias (*)
	float unit();                  // uniform in [0, 1), never 1
	Vec2 unit2();                  // two independent unit() numbers (*)
	bool coin_flip(float p);       // true with probability p
	// (*) Renders with low-discrepancy numbers (--sampler sobol, the renderer's default): integer(n)
	// is floor(u * n) of a 32-bit u (off uniform by at most 2^-32), and unit2() is one point of a 2D
	// sequence: its two numbers are stratified together.

	// Framework: a path's ray of `depth` begins (low-discrepancy numbers: its draws start at their
	// own dimensions, framework/render/owen_sobol.h).
	void begin_vertex(uint32_t depth);

private:
	friend struct RNG_State;
	friend RNG generator_for_sample(uint64_t, uint64_t, uint64_t, Sampler);

	uint32_t pcg32();
	bool draws_low_discrepancy() const;
	uint32_t next_low_discrepancy(bool two_d, uint32_t& y); // the next dimension's point (x, and y if 2D)

	uint64_t state = 0;
	uint64_t increment = 1;
	// Low-discrepancy numbers: the pixel's key (hashed with a dimension into its seeds), the sample index
	// bit-reversed, and the next dimension.
	bool low_discrepancy = false;
	uint32_t reversed_index = 0, dimension = 0;
	uint64_t pixel_key = 0;
};

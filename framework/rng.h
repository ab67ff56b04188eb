#pragma once
#include "math.h"

#include <string>

// The random numbers of a render (Render_Settings::sampler, --sampler).
enum class Sampler {
	// PCG32 (O'Neill 2014): every number independent of every other. The graders and the image
	// z-tests use it: their statistics (chi-square counts, a pixel's variance of the mean s^2 / n)
	// assume independent samples.
	independent,
	// Low-discrepancy: the pixel's samples are the points of an Owen-scrambled Sobol' sequence
	// (owen_sobol.h), one sequence per dimension (the n-th draw of a sample). Each sample is still
	// uniform, so every estimator stays unbiased, but the samples of a pixel are spread evenly
	// instead of clumping, and its error falls faster. Renders use it by default.
	sobol,
};
bool parse_sampler(const std::string& name, Sampler& sampler);
const char* sampler_name(Sampler sampler);

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
	static RNG for_sample(uint64_t render_seed, uint64_t pixel_index, uint64_t sample_index,
	                      Sampler sampler = Sampler::independent);

	uint32_t integer();            // uniform in [0, 2^32)
	uint32_t integer(uint32_t n);  // uniform in [0, n), n > 0, without modulo bias (*)
	float unit();                  // uniform in [0, 1), never 1
	Vec2 unit2();                  // two independent unit() numbers (*)
	bool coin_flip(float p);       // true with probability p
	// (*) Sampler::sobol: integer(n) is floor(u * n) of a 32-bit u (off uniform by at most 2^-32),
	// and unit2() is one point of a 2D sequence: its two numbers are stratified together.

	// Framework (Pathtracer::trace), Sampler::sobol only: the numbers drawn at the vertex a ray of
	// `depth` hits start at that vertex's own dimension, so that e.g. the first bounce's BSDF
	// sample uses the same sequence in every sample of a pixel, however many numbers the camera
	// drew. A vertex that draws more than its share continues into the next vertex's dimensions,
	// which then start after it: a dimension is never used twice in one sample.
	void begin_vertex(uint32_t depth);

	// Sampler::sobol: the first LOW_DISCREPANCY_DIMENSIONS draws of a sample (the camera's and
	// those of the first vertices) are low-discrepancy, the later ones independent (PCG32): the
	// first bounces carry most of an image's noise, and a scrambled point costs several times a
	// PCG32 draw.
	static constexpr uint32_t DIMENSIONS_PER_VERTEX = 8;
	static constexpr uint32_t LOW_DISCREPANCY_DIMENSIONS = 1 + 4 * DIMENSIONS_PER_VERTEX;

	// The generator's exact state, so that a grader can hand its student's code (in another
	// process, tests/judge/protocol.h) the very numbers it chose: the whole state, low-discrepancy
	// sequence included.
	struct State {
		uint64_t state = 0, increment = 1;
		bool low_discrepancy = false;
		uint32_t reversed_index = 0, dimension = 0;
		uint64_t pixel_key = 0;
	};
	State save() const {
		return State{state, increment, low_discrepancy, reversed_index, dimension, pixel_key};
	}
	static RNG restore(State saved) {
		RNG rng;
		rng.state = saved.state;
		rng.increment = saved.increment | 1u; // PCG's increment is odd
		rng.low_discrepancy = saved.low_discrepancy;
		rng.reversed_index = saved.reversed_index;
		rng.dimension = saved.dimension;
		rng.pixel_key = saved.pixel_key;
		return rng;
	}

private:
	uint32_t pcg32();
	bool draws_low_discrepancy() const;
	uint32_t next_low_discrepancy(bool two_d, uint32_t& y); // the next dimension's point (x, and y if 2D)

	uint64_t state = 0;
	uint64_t increment = 1;
	// Sampler::sobol: the pixel's key (hashed with a dimension into its seeds), the sample index
	// bit-reversed, and the next dimension.
	bool low_discrepancy = false;
	uint32_t reversed_index = 0, dimension = 0;
	uint64_t pixel_key = 0;
};

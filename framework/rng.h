#pragma once
#include "math.h"

// PCG32 random number generator (O'Neill 2014, "PCG: A family of simple fast space-efficient
// statistically good algorithms for random number generation"): 64-bit LCG state, XSH-RR output.
//
// Renders are deterministic: each pixel sample gets its own generator, seeded from
// (render seed, pixel index, sample index) by `RNG::for_sample`, so the image does not depend on
// the number of threads or the order of tiles.
class RNG {
public:
	explicit RNG(uint64_t seed = 0, uint64_t stream = 0);

	// A generator for one pixel sample.
	static RNG for_sample(uint64_t render_seed, uint64_t pixel_index, uint64_t sample_index);

	uint32_t integer();            // uniform in [0, 2^32)
	uint32_t integer(uint32_t n);  // uniform in [0, n), n > 0, without modulo bias
	float unit();                  // uniform in [0, 1), never 1
	Vec2 unit2();                  // two independent unit() numbers
	bool coin_flip(float p);       // true with probability p

	// The generator's exact state, so that a grader can hand its student's code (in another
	// process, tests/judge/protocol.h) the very numbers it chose.
	struct State {
		uint64_t state = 0, increment = 1;
	};
	State save() const {
		return State{state, increment};
	}
	static RNG restore(State saved) {
		RNG rng;
		rng.state = saved.state;
		rng.increment = saved.increment | 1u; // PCG's increment is odd
		return rng;
	}

private:
	uint64_t state = 0;
	uint64_t increment = 1;
};

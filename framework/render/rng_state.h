#pragma once
// A generator's exact state, for grading alone: a grader hands a student's code (in another
// process) the very numbers it chose, low-discrepancy sequence included.
#include "rng.h"

struct RNG_State {
	uint64_t state = 0, increment = 1;
	bool low_discrepancy = false;
	uint32_t reversed_index = 0, dimension = 0;
	uint64_t pixel_key = 0;

	static RNG_State of(const RNG& rng) {
		return RNG_State{rng.state, rng.increment, rng.low_discrepancy, rng.reversed_index, rng.dimension,
		                 rng.pixel_key};
	}
	RNG restored() const {
		RNG rng;
		rng.state = state;
		rng.increment = increment | 1u; // PCG's increment is odd
		rng.low_discrepancy = low_discrepancy;
		rng.reversed_index = reversed_index;
		rng.dimension = dimension;
		rng.pixel_key = pixel_key;
		return rng;
	}
};

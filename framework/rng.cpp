#include "rng.h"

namespace {
constexpr uint64_t PCG_MULTIPLIER = 6364136223846793005ull;

// SplitMix64 finalizer (Steele et al. 2014): a bijective 64-bit mix used to turn structured
// inputs (seed, pixel, sample) into well-spread PCG seeds and streams.
uint64_t mix64(uint64_t z) {
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
	return z ^ (z >> 31);
}
} // namespace

RNG::RNG(uint64_t seed, uint64_t stream) {
	// PCG32 seeding: the increment must be odd; advance once before and after adding the seed.
	increment = (stream << 1u) | 1u;
	state = 0;
	integer();
	state += seed;
	integer();
}

RNG RNG::for_sample(uint64_t render_seed, uint64_t pixel_index, uint64_t sample_index) {
	uint64_t seed = mix64(render_seed ^ mix64(pixel_index + 0x9e3779b97f4a7c15ull));
	return RNG(mix64(seed + sample_index), seed);
}

uint32_t RNG::integer() {
	uint64_t old = state;
	state = old * PCG_MULTIPLIER + increment;
	uint32_t xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
	uint32_t rot = uint32_t(old >> 59u);
	return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
}

uint32_t RNG::integer(uint32_t n) {
	// Lemire's rejection threshold: accept only values below the largest multiple of n.
	uint32_t threshold = (0u - n) % n;
	for (;;) {
		uint32_t r = integer();
		if (r >= threshold) return r % n;
	}
}

float RNG::unit() {
	// The top 24 bits scaled by 2^-24: exactly representable, in [0, 1 - 2^-24].
	return float(integer() >> 8) * 0x1p-24f;
}

Vec2 RNG::unit2() {
	float a = unit();
	float b = unit();
	return Vec2{a, b};
}

bool RNG::coin_flip(float p) {
	return unit() < p;
}

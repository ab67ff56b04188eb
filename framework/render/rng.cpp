#include "rng.h"
#include "owen_sobol.h"
#include "sampler.h"

#include <algorithm>

namespace {
constexpr uint64_t PCG_MULTIPLIER = 6364136223846793005ull;
constexpr uint64_t GOLDEN_GAMMA = 0x9e3779b97f4a7c15ull;

// SplitMix64 finalizer (Steele et al. 2014): a bijective 64-bit mix used to turn structured
// inputs (seed, pixel, sample, dimension) into well-spread PCG seeds, streams and scrambling seeds.
uint64_t mix64(uint64_t z) {
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
	return z ^ (z >> 31);
}

// The seed every generator of a pixel starts from.
uint64_t pixel_seed(uint64_t render_seed, uint64_t pixel_index) {
	return mix64(render_seed ^ mix64(pixel_index + GOLDEN_GAMMA));
}

// The top 24 bits scaled by 2^-24: exactly representable, in [0, 1 - 2^-24].
float to_unit(uint32_t bits) {
	return float(bits >> 8) * 0x1p-24f;
}
} // namespace

bool parse_sampler(const std::string& name, Sampler& sampler) {
	if (name != "independent" && name != "sobol") return false;
	sampler = name == "sobol" ? Sampler::sobol : Sampler::independent;
	return true;
}

const char* sampler_name(Sampler sampler) {
	return sampler == Sampler::sobol ? "sobol" : "independent";
}

RNG::RNG(uint64_t seed, uint64_t stream) {
	// PCG32 seeding: the increment must be odd; advance once before and after adding the seed.
	increment = (stream << 1u) | 1u;
	state = 0;
	pcg32();
	state += seed;
	pcg32();
}

RNG RNG::for_sample(uint64_t render_seed, uint64_t pixel_index, uint64_t sample_index) {
	uint64_t seed = pixel_seed(render_seed, pixel_index);
	return RNG(mix64(seed + sample_index), seed);
}

RNG generator_for_sample(uint64_t render_seed, uint64_t pixel_index, uint64_t sample_index, Sampler sampler) {
	RNG rng = RNG::for_sample(render_seed, pixel_index, sample_index);
	if (sampler == Sampler::sobol) {
		rng.low_discrepancy = true;
		rng.pixel_key = pixel_seed(render_seed, pixel_index); // every sample of the pixel shares the scrambling
		rng.reversed_index = owen_sobol::reverse_bits(uint32_t(sample_index));
	}
	return rng;
}

void RNG::begin_vertex(uint32_t depth) {
	uint64_t first = 1 + uint64_t(depth) * owen_sobol::DIMENSIONS_PER_VERTEX; // dimension 0 is the camera's
	dimension = std::max(dimension, uint32_t(std::min<uint64_t>(first, owen_sobol::LOW_DISCREPANCY_DIMENSIONS)));
}

bool RNG::draws_low_discrepancy() const {
	return low_discrepancy && dimension < owen_sobol::LOW_DISCREPANCY_DIMENSIONS;
}

uint32_t RNG::next_low_discrepancy(bool two_d, uint32_t& y) {
	uint64_t hash = mix64(pixel_key + GOLDEN_GAMMA * (uint64_t(dimension) + 1));
	dimension++;
	uint32_t shuffled = owen_sobol::shuffled_index(reversed_index, uint32_t(hash));
	if (two_d) y = owen_sobol::dimension_1(shuffled, uint32_t(mix64(hash)));
	return owen_sobol::dimension_0(shuffled, uint32_t(hash >> 32));
}

uint32_t RNG::pcg32() {
	uint64_t old = state;
	state = old * PCG_MULTIPLIER + increment;
	uint32_t xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
	uint32_t rot = uint32_t(old >> 59u);
	return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
}

uint32_t RNG::integer() {
	uint32_t unused;
	return draws_low_discrepancy() ? next_low_discrepancy(false, unused) : pcg32();
}

uint32_t RNG::integer(uint32_t n) {
	if (draws_low_discrepancy()) return uint32_t((uint64_t(integer()) * n) >> 32); // floor(u * n)
	// Lemire's rejection threshold: accept only values below the largest multiple of n.
	uint32_t threshold = (0u - n) % n;
	for (;;) {
		uint32_t r = pcg32();
		if (r >= threshold) return r % n;
	}
}

float RNG::unit() {
	return to_unit(integer());
}

Vec2 RNG::unit2() {
	if (draws_low_discrepancy()) {
		uint32_t y = 0;
		uint32_t x = next_low_discrepancy(true, y);
		return Vec2{to_unit(x), to_unit(y)};
	}
	float a = unit();
	float b = unit();
	return Vec2{a, b};
}

bool RNG::coin_flip(float p) {
	return unit() < p;
}

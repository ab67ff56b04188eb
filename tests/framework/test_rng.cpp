// The random number generator (framework/api/rng.h): ranges, independence of the per-sample streams,
// and uniformity.
#include "rng.h"
#include "statistics.h"

#include "lab_catch2.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <set>
#include <vector>

namespace {

// The chi-square tests in this file share the significance level (Šidák correction).
constexpr double ALPHA = 0.01;
constexpr size_t CHI2_TESTS = 3;

// Pearson's chi-square test that `bins` counts of `draw()` (each in [0, bins)) are uniform.
stats::Chi2_Result uniformity_test(size_t bins, size_t samples, const std::function<size_t()>& draw) {
	std::vector<double> observed(bins, 0.0);
	for (size_t i = 0; i < samples; i++) observed[draw()] += 1.0;
	std::vector<double> expected(bins, double(samples) / double(bins));
	return stats::chi2_test(observed, expected);
}

size_t bin_of(float u, size_t bins) {
	return std::min(size_t(u * float(bins)), bins - 1);
}

} // namespace

TEST_CASE("RNG::unit is in [0, 1) on a grid of 2^-24: its largest value is 1 - 2^-24, never 1") {
	RNG rng(42);
	for (int i = 0; i < 1000000; i++) {
		float u = rng.unit();
		bool on_grid = u * 0x1p24f == std::floor(u * 0x1p24f); // a multiple of 2^-24
		if (u >= 0.0f && u < 1.0f && on_grid) continue;
		INFO("draw " << i << ": unit() = " << u);
		FAIL("unit() must return one of the values k * 2^-24, k = 0 .. 2^24 - 1 (framework/render/rng.cpp)");
	}
	// The top 24 output bits are all ones for about one generator in 2^24: search the first draw
	// of successive seeds for a few such cases. A conversion that rounds (e.g. float(x) * 2^-32)
	// would return exactly 1 for half of them.
	const float largest = 1.0f - 0x1p-24f;
	int found = 0;
	for (uint64_t seed = 0; found < 4 && seed < (uint64_t(1) << 28); seed++) {
		float u = RNG(seed).unit();
		if (u >= largest) {
			INFO("RNG(" << seed << ").unit() = " << u);
			CHECK(u == largest);
			found++;
		}
	}
	CHECK(found == 4);
}

TEST_CASE("RNG::integer(n) is in [0, n) and has no modulo bias") {
	RNG rng(7);
	for (uint32_t n : {1u, 2u, 3u, 7u, 1000u, 0x80000001u, 0xffffffffu}) {
		for (int i = 0; i < 10000; i++) {
			uint32_t k = rng.integer(n);
			if (k < n) continue;
			INFO("integer(" << n << ") returned " << k);
			FAIL("integer(n) must be below n (framework/render/rng.cpp)");
		}
	}
	// With n = 3 * 2^30, a plain integer() % n returns [0, 2^30) twice as often as the rest:
	// the three thirds of [0, n) must be equally likely.
	const uint32_t n = 3u << 30;
	auto result = uniformity_test(3, 300000, [&] { return size_t(rng.integer(n) / (1u << 30)); });
	CAPTURE(result.statistic, result.dof, result.p_value);
	CHECK(result.p_value > stats::sidak(ALPHA, CHI2_TESTS));
}

TEST_CASE("RNG::unit is uniform: chi-square over 100 bins, 10^6 draws") {
	RNG rng(2024);
	const size_t bins = 100;
	auto result = uniformity_test(bins, 1000000, [&] { return bin_of(rng.unit(), bins); });
	CAPTURE(result.statistic, result.dof, result.p_value);
	CHECK(result.p_value > stats::sidak(ALPHA, CHI2_TESTS));
}

TEST_CASE("RNG::for_sample: the first draws of neighbouring pixels are uniform") {
	// Pixels are seeded from consecutive indices; a weak mix would show up as structure here.
	const size_t bins = 100;
	uint64_t pixel = 0;
	auto result = uniformity_test(bins, 1000000, [&] { return bin_of(RNG::for_sample(3, pixel++, 0).unit(), bins); });
	CAPTURE(result.statistic, result.dof, result.p_value);
	CHECK(result.p_value > stats::sidak(ALPHA, CHI2_TESTS));
}

TEST_CASE("RNG::for_sample gives a different stream to every (seed, pixel, sample) and the same one again") {
	auto first_draws = [](uint64_t seed, uint64_t pixel, uint64_t sample) {
		RNG rng = RNG::for_sample(seed, pixel, sample);
		std::array<uint32_t, 4> draws{};
		for (uint32_t& d : draws) d = rng.integer();
		return draws;
	};
	std::set<std::array<uint32_t, 4>> streams;
	size_t count = 0;
	for (uint64_t seed : {0ull, 1ull, 2ull, 0xdeadbeefull}) {
		for (uint64_t pixel = 0; pixel < 64; pixel++) {
			for (uint64_t sample = 0; sample < 64; sample++) {
				auto draws = first_draws(seed, pixel, sample);
				INFO("seed " << seed << ", pixel " << pixel << ", sample " << sample);
				REQUIRE(draws == first_draws(seed, pixel, sample));
				streams.insert(draws);
				count++;
			}
		}
	}
	// Four 32-bit draws collide by chance with probability about count^2 / 2^129: never.
	CHECK(streams.size() == count);
}

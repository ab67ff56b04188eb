// The low-discrepancy numbers of Sampler::sobol (framework/render/sampler.h, owen_sobol.h): the
// samples of a pixel are stratified (the first 2^k of them are a (0,k,2)-net in every 2D draw and
// one point per interval of 1/2^k in every 1D draw), each sample is uniform over the pixels (so
// that estimators stay unbiased), and a path's vertices draw from dimensions of their own, never
// one twice.
#include "owen_sobol.h"
#include "rng.h"
#include "sampler.h"
#include "statistics.h"

#include "lab_catch2.h"

#include <algorithm>
#include <functional>
#include <set>
#include <vector>

namespace {

constexpr double ALPHA = 0.01;
constexpr size_t CHI2_TESTS = 3; // this file's chi-square tests share ALPHA (Šidák)

// The first `n` draws of dimension `dimension` (earlier dimensions drawn and discarded) of every
// sample of one pixel.
std::vector<Vec2> pixel_points(uint64_t seed, uint64_t pixel, uint32_t n, uint32_t dimension, bool two_d) {
	std::vector<Vec2> points;
	for (uint32_t s = 0; s < n; s++) {
		RNG rng = generator_for_sample(seed, pixel, s, Sampler::sobol);
		for (uint32_t d = 0; d < dimension; d++) rng.unit();
		points.push_back(two_d ? rng.unit2() : Vec2{rng.unit(), 0.5f});
	}
	return points;
}

// Whether every box of 2^a x 2^(k - a) cells (a = 0 .. k) of the unit square holds exactly one of
// the 2^k points: the definition of a (0,k,2)-net in base 2.
std::string net_violation(const std::vector<Vec2>& points, uint32_t k) {
	for (uint32_t a = 0; a <= k; a++) {
		uint32_t nx = 1u << a, ny = 1u << (k - a);
		std::vector<int> count(size_t(nx) * ny, 0);
		for (Vec2 p : points) count[size_t(p.y * float(ny)) * nx + size_t(p.x * float(nx))]++;
		auto bad = std::find_if(count.begin(), count.end(), [](int c) { return c != 1; });
		if (bad != count.end())
			return std::to_string(nx) + " x " + std::to_string(ny) + " cells: cell " +
			       std::to_string(bad - count.begin()) + " holds " + std::to_string(*bad) + " points";
	}
	return "";
}

stats::Chi2_Result uniformity(const std::vector<size_t>& cells, size_t bins) {
	std::vector<double> observed(bins, 0.0);
	for (size_t c : cells) observed[c] += 1.0;
	return stats::chi2_test(observed, std::vector<double>(bins, double(cells.size()) / double(bins)));
}

} // namespace

TEST_CASE("Sampler::sobol: the first 2^k samples of a pixel are a (0,k,2)-net in every 2D draw", "[sobol]") {
	for (uint64_t pixel : {0ull, 1ull, 977ull}) {
		for (uint32_t dimension : {0u, 1u, 5u, 20u}) {
			for (uint32_t k : {1u, 4u, 8u}) {
				std::vector<Vec2> points = pixel_points(11, pixel, 1u << k, dimension, true);
				INFO("pixel " << pixel << ", dimension " << dimension << ", the first " << (1u << k) << " samples");
				CHECK(net_violation(points, k) == "");
			}
		}
	}
}

TEST_CASE("Sampler::sobol: the first 2^k samples of a pixel put one 1D draw in each interval of 1/2^k",
          "[sobol]") {
	for (uint32_t dimension : {0u, 3u, 17u}) {
		std::vector<Vec2> points = pixel_points(5, 42, 256, dimension, false);
		std::set<int> cells;
		for (Vec2 p : points) cells.insert(int(p.x * 256.0f));
		INFO("dimension " << dimension << ": 256 samples fill " << cells.size() << " of the 256 intervals");
		CHECK(cells.size() == 256);
	}
}

TEST_CASE("Sampler::sobol: a sample's point is uniform over the pixels (chi-square, 16 x 16 cells)", "[sobol]") {
	// Owen scrambling makes every single point uniform on the square: what keeps estimators
	// unbiased. Sample 5, dimension 2, over 100000 pixels.
	std::vector<size_t> cells;
	for (uint64_t pixel = 0; pixel < 100000; pixel++) {
		RNG rng = generator_for_sample(3, pixel, 5, Sampler::sobol);
		rng.unit2();
		rng.unit();
		Vec2 p = rng.unit2();
		cells.push_back(size_t(p.y * 16.0f) * 16 + size_t(p.x * 16.0f));
	}
	stats::Chi2_Result result = uniformity(cells, 256);
	CAPTURE(result.statistic, result.dof, result.p_value);
	CHECK(result.p_value > stats::sidak(ALPHA, CHI2_TESTS));
}

TEST_CASE("Sampler::sobol: two dimensions of one sample are independent (chi-square over the pixels)", "[sobol]") {
	// Each dimension shuffles the order of its points with its own seed: dimension 1's x against
	// dimension 4's x, sample 9, over 100000 pixels, on a 16 x 16 grid.
	std::vector<size_t> cells;
	for (uint64_t pixel = 0; pixel < 100000; pixel++) {
		RNG rng = generator_for_sample(8, pixel, 9, Sampler::sobol);
		rng.unit();
		float a = rng.unit();
		rng.unit2();
		rng.unit();
		float b = rng.unit();
		cells.push_back(size_t(a * 16.0f) * 16 + size_t(b * 16.0f));
	}
	stats::Chi2_Result result = uniformity(cells, 256);
	CAPTURE(result.statistic, result.dof, result.p_value);
	CHECK(result.p_value > stats::sidak(ALPHA, CHI2_TESTS));
}

TEST_CASE("Sampler::sobol: draws past the low-discrepancy dimensions are independent and uniform", "[sobol]") {
	std::vector<size_t> cells;
	for (uint64_t pixel = 0; pixel < 1000; pixel++) {
		RNG rng = generator_for_sample(4, pixel, 0, Sampler::sobol);
		rng.begin_vertex(1000); // far past owen_sobol::LOW_DISCREPANCY_DIMENSIONS
		for (int i = 0; i < 100; i++) cells.push_back(size_t(rng.unit() * 100.0f));
	}
	stats::Chi2_Result result = uniformity(cells, 100);
	CAPTURE(result.statistic, result.dof, result.p_value);
	CHECK(result.p_value > stats::sidak(ALPHA, CHI2_TESTS));
}

TEST_CASE("RNG::begin_vertex: a vertex's draws start at its own dimension, and none is drawn twice", "[sobol]") {
	// The first draw at vertex 1 is dimension 1 + DIMENSIONS_PER_VERTEX, however few numbers the
	// camera and vertex 0 drew; if vertex 0 drew more than its share, vertex 1 continues after them.
	auto draws = [](uint32_t at_vertex_0, uint32_t at_vertex_1) {
		RNG rng = generator_for_sample(1, 2, 3, Sampler::sobol);
		std::vector<uint32_t> values{rng.integer()}; // the camera's dimension 0
		rng.begin_vertex(0);
		for (uint32_t i = 0; i < at_vertex_0; i++) values.push_back(rng.integer());
		rng.begin_vertex(1);
		for (uint32_t i = 0; i < at_vertex_1; i++) values.push_back(rng.integer());
		return values;
	};
	const uint32_t per_vertex = owen_sobol::DIMENSIONS_PER_VERTEX;
	std::vector<uint32_t> few = draws(2, 1), all = draws(per_vertex, 1), more = draws(per_vertex + 2, 1);
	CHECK(few.back() == all.back()); // vertex 1's first dimension either way
	CHECK(more[per_vertex + 1] == all.back()); // vertex 0's extra draws take vertex 1's dimensions...
	std::set<uint32_t> distinct(more.begin(), more.end());
	CHECK(distinct.size() == more.size()); // ... and vertex 1 continues after them
}

TEST_CASE("Sampler::sobol: integer(n) is in [0, n) and coin_flip follows p", "[sobol]") {
	size_t heads = 0, n = 4096;
	for (uint32_t s = 0; s < n; s++) {
		RNG rng = generator_for_sample(2, 7, s, Sampler::sobol);
		uint32_t k = rng.integer(3);
		REQUIRE(k < 3);
		heads += rng.coin_flip(0.25f);
	}
	// 4096 stratified coin flips of one pixel: exactly a quarter come up heads.
	CHECK(heads == n / 4);
}

TEST_CASE("owen_sobol::pascal is the second dimension of Sobol's sequence", "[sobol]") {
	// Direction numbers m_k = 1 (Joe and Kuo's first line): points 0 .. 7 are 0, 1/2, 3/4, 1/4, 5/8,
	// 1/8, 3/8, 7/8.
	const double expected[] = {0.0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875};
	for (uint32_t i = 0; i < 8; i++) {
		double x = double(owen_sobol::reverse_bits(owen_sobol::pascal(i))) * 0x1p-32;
		CAPTURE(i);
		CHECK(x == expected[i]);
	}
}

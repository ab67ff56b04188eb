// Task 3, handout §3.2: the tree BVH::build makes satisfies the layout contract of bvh.h, also on
// degenerate inputs (no primitives, one, identical ones, a flat mesh).
#include "bvh_oracle.h"
#include "bvh_test_scenes.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>

namespace {

// Triangles as comparable byte strings, sorted: equal multisets give equal vectors.
std::vector<std::string> multiset(const std::vector<Triangle>& triangles) {
	std::vector<std::string> keys;
	for (const Triangle& t : triangles) {
		std::string key(sizeof(Triangle), '\0');
		std::memcpy(key.data(), &t, sizeof(Triangle));
		keys.push_back(key);
	}
	std::sort(keys.begin(), keys.end());
	return keys;
}

void check_structure(const std::vector<Triangle>& triangles, size_t max_leaf_size) {
	BVH<Triangle> bvh(std::vector<Triangle>(triangles), max_leaf_size);
	INFO(triangles.size() << " triangles, max_leaf_size = " << max_leaf_size);
	{
		INFO("BVH::build must keep every primitive exactly once in `primitives`, reordered, not copied or "
		     "dropped (handout §3.2)");
		REQUIRE(bvh.primitives.size() == triangles.size());
		REQUIRE(multiset(bvh.primitives) == multiset(triangles));
	}
	std::string problem = oracle::check_structure(bvh, max_leaf_size);
	INFO("BVH::build: " << problem << " (handout §3.2, layout in bvh.h)");
	CHECK(problem.empty());
}

// The closest hit of one ray by testing every triangle.
Trace closest_of(const std::vector<Triangle>& triangles, const Ray& ray) {
	Trace closest;
	for (const Triangle& t : triangles) closest = Trace::min(closest, t.hit(ray));
	return closest;
}

} // namespace

TEST_CASE("BVH::build: every primitive once, node ranges nested and tight boxes, small leaves",
          "[task3][bvh][structure]") {
	RNG rng(311);
	std::vector<Triangle> soup = random_soup(rng, 3000, 0.08f);
	std::vector<Triangle> clusters = clustered_soup(rng);
	for (size_t max_leaf_size : {1, 2, 4, 8}) {
		check_structure(soup, max_leaf_size);
		check_structure(clusters, max_leaf_size);
	}
}

TEST_CASE("BVH with no primitives: hit misses, bbox is empty", "[task3][bvh][degenerate]") {
	BVH<Triangle> bvh(std::vector<Triangle>{}, 4);
	INFO("BVH::build over zero primitives (handout §3.2): no crash, and hit() must miss");
	CHECK(oracle::check_structure(bvh, 4).empty());
	CHECK(bvh.bbox().empty());
	CHECK_FALSE(bvh.hit(Ray{Vec3{0.0f}, Vec3{0.0f, 0.0f, 1.0f}}).hit);
	CHECK_FALSE(bvh.hit(Ray{Vec3{0.0f, 0.0f, -5.0f}, Vec3{0.0f, 0.0f, 1.0f}}).hit);
}

TEST_CASE("BVH with one primitive: a leaf root, hits like the triangle itself", "[task3][bvh][degenerate]") {
	RNG rng(312);
	std::vector<Triangle> one{make_triangle(rng, {0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f})};
	check_structure(one, 1);
	BVH<Triangle> bvh(std::vector<Triangle>(one), 1);
	const Ray rays[] = {Ray{{0.25f, 0.25f, 1.0f}, {0.0f, 0.0f, -1.0f}}, Ray{{0.75f, 0.75f, 1.0f}, {0.0f, 0.0f, -1.0f}},
	                    Ray{{-1.0f, -1.0f, -1.0f}, {1.2f, 1.1f, 1.0f}}, Ray{{0.25f, 0.25f, 1.0f}, {0.0f, 0.0f, 1.0f}}};
	for (const Ray& ray : rays) {
		Trace want = one[0].hit(ray), got = bvh.hit(ray);
		INFO("ray " << describe(ray) << ": the one-triangle BVH must hit exactly when the triangle does (a flat box: "
		                                "handout §3.1)");
		CHECK(got.hit == want.hit);
		if (got.hit && want.hit) CHECK(got.distance == want.distance);
	}
}

TEST_CASE("BVH over identical triangles (all centroids coincide): the build ends, hits are right",
          "[task3][bvh][degenerate]") {
	RNG rng(313);
	std::vector<Triangle> same(500, make_triangle(rng, {0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.5f}, {0.0f, 1.0f, 1.0f}));
	// Different triangles around one centroid: coincident centroids, but different boxes.
	std::vector<Triangle> around;
	for (int i = 0; i < 300; i++) {
		// Vertices a, -a and b with |b| <= |a| per axis: the box is [-|a|, |a|], centred at 0.
		Vec3 a{rng.unit() - 0.5f, rng.unit() - 0.5f, rng.unit() - 0.5f};
		Vec3 b = a * Vec3{2.0f * rng.unit() - 1.0f, 2.0f * rng.unit() - 1.0f, 2.0f * rng.unit() - 1.0f};
		around.push_back(make_triangle(rng, a, -a, b));
	}
	INFO("when all centroids coincide no split can separate them: make a leaf or split by count, but never "
	     "recurse forever (handout §3.2)");
	for (size_t max_leaf_size : {1, 4}) {
		check_structure(same, max_leaf_size);
		check_structure(around, max_leaf_size);
		for (const auto* triangles : {&same, &around}) {
			BVH<Triangle> bvh(std::vector<Triangle>(*triangles), max_leaf_size);
			std::vector<Ray> rays = random_rays(rng, bounds_of(*triangles), *triangles, 400);
			std::string report = compare_with_brute_force(bvh, rays, brute_force(*triangles, rays));
			INFO(report);
			CHECK(report.empty());
		}
	}
}

TEST_CASE("BVH over a flat mesh (every box flat in z): structure and hits", "[task3][bvh][degenerate]") {
	RNG rng(314);
	const int n = 24;
	std::vector<Triangle> grid = planar_grid(rng, n);
	for (size_t max_leaf_size : {1, 4}) check_structure(grid, max_leaf_size);

	// Rays at points inside the cells (away from the cell borders, where the triangles' slack for
	// rounding reaches beyond their boxes), from above and below, straight and oblique; rays
	// straight down through grid vertices (origins on box planes, d.x = d.y = 0); rays in the plane.
	std::vector<Ray> rays;
	for (int k = 0; k < 6000; k++) {
		Vec3 target{float(rng.integer(n)) + 0.02f + 0.96f * rng.unit(), float(rng.integer(n)) + 0.02f + 0.96f * rng.unit(),
		            0.0f};
		Vec3 origin = k % 2 ? target + Vec3{0.0f, 0.0f, 3.0f} : Vec3{n * rng.unit(), n * rng.unit(), -4.0f};
		rays.emplace_back(origin, target - origin);
	}
	for (int k = 0; k < 2000; k++) {
		Vec3 vertex{float(rng.integer(n + 1)), float(rng.integer(n + 1)), 0.0f};
		rays.emplace_back(vertex + Vec3{0.0f, 0.0f, 2.0f}, Vec3{0.0f, 0.0f, -1.0f});
		rays.emplace_back(vertex, Vec3{1.0f, 0.5f, 0.0f}); // lies in the plane: parallel, so no triangle is hit
	}
	std::vector<Brute_Force_Hit> expected = brute_force(grid, rays);
	for (size_t max_leaf_size : {1, 4}) {
		BVH<Triangle> bvh(std::vector<Triangle>(grid), max_leaf_size);
		INFO("a planar mesh has flat boxes everywhere: BBox::hit must accept enter == exit (handout §3.1); "
		     "max_leaf_size = "
		     << max_leaf_size);
		std::string report = compare_with_brute_force(bvh, rays, expected);
		INFO(report);
		CHECK(report.empty());
	}
	INFO("grader self-check: a ray straight down through a grid vertex hits the grid");
	REQUIRE(closest_of(grid, Ray{{1.0f, 1.0f, 2.0f}, {0.0f, 0.0f, -1.0f}}).hit);
}

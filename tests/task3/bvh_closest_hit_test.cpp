// Task 3, handout §3.3: BVH::hit returns exactly the closest hit that testing every triangle finds,
// on random triangle soups and real meshes, for several leaf sizes.
#include "bvh_test_scenes.h"
#include "obj_loader.h"

#include <catch2/catch.hpp>

namespace {

// Builds a BVH over `triangles` for each leaf size and compares it with brute force, each leaf
// size on every third ray (brute force is the expensive part, so each ray is traced once).
void check_against_brute_force(const std::vector<Triangle>& triangles, const std::vector<Ray>& rays) {
	std::vector<Brute_Force_Hit> expected = brute_force(triangles, rays);
	size_t hits = 0;
	for (const Brute_Force_Hit& e : expected) hits += e.closest.hit;
	INFO("grader self-check: the rays must hit the scene often enough to test anything");
	REQUIRE(hits > rays.size() / 4);

	const size_t leaf_sizes[] = {1, 4, 8};
	for (size_t k = 0; k < 3; k++) {
		std::vector<Ray> some_rays;
		std::vector<Brute_Force_Hit> some_expected;
		for (size_t i = k; i < rays.size(); i += 3) {
			some_rays.push_back(rays[i]);
			some_expected.push_back(expected[i]);
		}
		BVH<Triangle> bvh(std::vector<Triangle>(triangles), leaf_sizes[k]);
		INFO(triangles.size() << " triangles, BVH built with max_leaf_size = " << leaf_sizes[k]);
		std::string report = compare_with_brute_force(bvh, some_rays, some_expected);
		INFO(report);
		CHECK(report.empty());
	}
}

std::vector<Triangle> load_mesh(const std::string& path) {
	INFO("grader self-check: the lab's meshes must load (run the grader from the repository root)");
	std::vector<Triangle> triangles;
	REQUIRE_NOTHROW(triangles = load_obj(path));
	REQUIRE(!triangles.empty());
	return triangles;
}

} // namespace

TEST_CASE("BVH::hit equals brute force on a random triangle soup", "[task3][bvh][closest_hit]") {
	RNG rng(301);
	std::vector<Triangle> triangles = random_soup(rng, 1000, 0.1f);
	check_against_brute_force(triangles, random_rays(rng, bounds_of(triangles), triangles, 50000));
}

TEST_CASE("BVH::hit equals brute force on clustered triangles with a few large ones", "[task3][bvh][closest_hit]") {
	RNG rng(302);
	std::vector<Triangle> triangles = clustered_soup(rng);
	check_against_brute_force(triangles, random_rays(rng, bounds_of(triangles), triangles, 20000));
}

TEST_CASE("BVH::hit equals brute force on the bunny mesh", "[task3][bvh][closest_hit]") {
	RNG rng(303);
	std::vector<Triangle> triangles = load_mesh("scenes/meshes/bunny_npm_lowres.obj");
	check_against_brute_force(triangles, random_rays(rng, bounds_of(triangles), triangles, 20000));
}

TEST_CASE("BVH::hit equals brute force on the dragon mesh", "[task3][bvh][closest_hit]") {
	RNG rng(304);
	std::vector<Triangle> triangles = load_mesh("scenes/meshes/dragon_vrip_res4.obj");
	check_against_brute_force(triangles, random_rays(rng, bounds_of(triangles), triangles, 10000));
}

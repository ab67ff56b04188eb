// Task 3, handout §3.3: BVH::hit returns exactly the closest hit that testing every triangle finds,
// on random triangle soups and real meshes, for several leaf sizes. The student's BVH is built and
// asked in the subject; the expected hits are the reference's, brute force the final word (Closest_Hits).
#include "bvh_test_scenes.h"
#include "judge.h"

#include "lab_catch2.h"

using protocol::BVH_Triangles;

namespace {

// Builds a BVH over `triangles` for each leaf size and compares it with brute force, each leaf
// size on every third ray. The four scenes below ask 85 000 rays in all: a traversal bug that
// returns a wrong hit for one ray in 10 000 is caught with probability 1 - exp(-8.5) > 0.9997. The
// starter's one-leaf BVH tests every triangle for every ray, so the largest meshes get fewer rays
// (dragon: 5 000; clusters: 10 000), which keeps its verdict within 5 s (issue 20).
void check_against_brute_force(const std::vector<Triangle>& triangles, const std::vector<Ray>& rays) {
	Closest_Hits expected(triangles);
	REQUIRE(expected.hitting(rays) > rays.size() / 4); // the grader's own rays must hit often enough to test anything

	const size_t leaf_sizes[] = {1, 4, 8};
	for (size_t k = 0; k < 3; k++) {
		std::vector<Ray> some_rays;
		for (size_t i = k; i < rays.size(); i += 3) some_rays.push_back(rays[i]);
		BVH_Triangles::Answer answer = judge::ask(BVH_Triangles{triangles, leaf_sizes[k], some_rays});
		INFO(triangles.size() << " triangles, BVH built with max_leaf_size = " << leaf_sizes[k]);
		std::string report = expected.compare(answer.hits, some_rays);
		INFO(report);
		CHECK(report.empty());
		if (!report.empty()) return;
	}
}

} // namespace

TEST_CASE("BVH::hit equals brute force on a random triangle soup", "[id:t3.bvh.closest-hit-soup][task3][bvh][closest_hit][fn:BVH::hit][uses:BBox::hit][uses:BVH::build]") {
	RNG rng(scene_seed(301));
	std::vector<Triangle> triangles = random_soup(rng, 1000, 0.1f);
	check_against_brute_force(triangles, random_rays(rng, bounds_of(triangles), triangles, 50000));
}

TEST_CASE("BVH::hit equals brute force on clustered triangles with a few large ones", "[id:t3.bvh.closest-hit-clustered][task3][bvh][closest_hit][fn:BVH::hit][uses:BBox::hit][uses:BVH::build]") {
	RNG rng(scene_seed(302));
	std::vector<Triangle> triangles = clustered_soup(rng);
	check_against_brute_force(triangles, random_rays(rng, bounds_of(triangles), triangles, 10000));
}

TEST_CASE("BVH::hit equals brute force on the bunny mesh", "[id:t3.bvh.closest-hit-bunny][task3][bvh][closest_hit][fn:BVH::hit][uses:BBox::hit][uses:BVH::build]") {
	RNG rng(scene_seed(303));
	std::vector<Triangle> triangles = load_placed_mesh("scenes/meshes/bunny_npm_lowres.obj");
	check_against_brute_force(triangles, random_rays(rng, bounds_of(triangles), triangles, 20000));
}

TEST_CASE("BVH::hit equals brute force on the dragon mesh", "[id:t3.bvh.closest-hit-dragon][task3][bvh][closest_hit][fn:BVH::hit][uses:BBox::hit][uses:BVH::build]") {
	RNG rng(scene_seed(304));
	std::vector<Triangle> triangles = load_placed_mesh("scenes/meshes/dragon_vrip_res4.obj");
	check_against_brute_force(triangles, random_rays(rng, bounds_of(triangles), triangles, 5000));
}

// Task 3, handout §3.2: the tree BVH::build makes satisfies the layout contract of bvh.h, also on
// degenerate inputs (no primitives, one, identical ones, a flat mesh). The student's tree comes
// from the subject (protocol::BVH_Triangles); the checks run here (tree_check.h).
#include "bvh_test_scenes.h"
#include "judge.h"
#include "tree_check.h"

#include "lab_catch2.h"

#include <algorithm>
#include <cstring>

using protocol::BVH_Triangles;

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

// Whether the student's tree over `triangles` keeps the contract; fails the test case if not.
bool check_structure(const std::vector<Triangle>& triangles, size_t max_leaf_size, const BVH_Triangles::Answer& answer) {
	INFO(triangles.size() << " triangles, max_leaf_size = " << max_leaf_size);
	{
		INFO("BVH::build must keep every primitive exactly once in `primitives`, reordered, not copied or "
		     "dropped (handout §3.2)");
		CHECK(answer.primitives.size() == triangles.size());
		bool same = multiset(answer.primitives) == multiset(triangles);
		CHECK(same);
		if (!same) return false;
	}
	std::string problem = task3::structure_problem(answer.tree, boxes_of(answer.primitives), max_leaf_size);
	INFO("BVH::build: " << problem << " (handout §3.2, layout in bvh.h)");
	CHECK(problem.empty());
	return problem.empty();
}

bool check_structure(const std::vector<Triangle>& triangles, size_t max_leaf_size) {
	return check_structure(triangles, max_leaf_size, judge::ask(BVH_Triangles{triangles, max_leaf_size, {}}));
}

} // namespace

TEST_CASE("BVH::build: every primitive once, node ranges nested and tight boxes, small leaves",
          "[id:t3.bvh.structure][task3][bvh][structure][fn:BVH::build]") {
	RNG rng(scene_seed(311));
	std::vector<Triangle> soup = random_soup(rng, 3000, 0.08f);
	std::vector<Triangle> clusters = clustered_soup(rng);
	for (size_t max_leaf_size : {1, 2, 4, 8}) {
		if (!check_structure(soup, max_leaf_size) || !check_structure(clusters, max_leaf_size)) return;
	}
}

TEST_CASE("BVH with no primitives: hit misses, bbox is empty", "[id:t3.bvh.empty][task3][bvh][degenerate][fn:BVH::build][fn:BVH::hit]") {
	std::vector<Ray> rays{Ray{Vec3{0.0f}, Vec3{0.0f, 0.0f, 1.0f}}, Ray{Vec3{0.0f, 0.0f, -5.0f}, Vec3{0.0f, 0.0f, 1.0f}}};
	BVH_Triangles::Answer answer = judge::ask(BVH_Triangles{{}, 4, rays});
	INFO("BVH::build over zero primitives (handout §3.2): no crash, no node with a box, and hit() must miss");
	CHECK(task3::structure_problem(answer.tree, {}, 4).empty());
	bool empty_box = answer.tree.nodes.empty() || answer.tree.nodes.at(answer.tree.root_idx).bbox.empty();
	CHECK(empty_box);
	for (const Trace& hit : answer.hits) CHECK_FALSE(hit.hit);
}

TEST_CASE("BVH with one primitive: a leaf root, hits like the triangle itself", "[id:t3.bvh.one-primitive][task3][bvh][degenerate][fn:BVH::build][fn:BVH::hit][uses:BBox::hit]") {
	RNG rng(scene_seed(312));
	std::vector<Triangle> one{make_triangle(rng, {0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f})};
	const std::vector<Ray> rays{Ray{{0.25f, 0.25f, 1.0f}, {0.0f, 0.0f, -1.0f}}, Ray{{0.75f, 0.75f, 1.0f}, {0.0f, 0.0f, -1.0f}},
	                            Ray{{-1.0f, -1.0f, -1.0f}, {1.2f, 1.1f, 1.0f}}, Ray{{0.25f, 0.25f, 1.0f}, {0.0f, 0.0f, 1.0f}}};
	BVH_Triangles::Answer answer = judge::ask(BVH_Triangles{one, 1, rays});
	if (!check_structure(one, 1, answer)) return;
	for (size_t i = 0; i < rays.size(); i++) {
		Trace want = one[0].hit(rays[i]), got = answer.hits[i];
		INFO("ray " << describe(rays[i]) << ": the one-triangle BVH must hit exactly when the triangle does (a flat "
		                                    "box: handout §3.1)");
		CHECK(got.hit == want.hit);
		if (got.hit && want.hit) CHECK(got.distance == want.distance);
	}
}

TEST_CASE("BVH over identical triangles (all centroids coincide): the build ends, hits are right",
          "[id:t3.bvh.identical-centroids][task3][bvh][degenerate][fn:BVH::build][fn:BVH::hit][uses:BBox::hit]") {
	RNG rng(scene_seed(313));
	std::vector<Triangle> same(500, make_triangle(rng, {0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.5f}, {0.0f, 1.0f, 1.0f}));
	// Different triangles around one centroid: coincident centroids, but different boxes.
	std::vector<Triangle> around;
	for (int i = 0; i < 300; i++) {
		// Vertices a, -a and b with |b| <= |a| per axis: the box is [-|a|, |a|], centred at 0.
		Vec3 a{rng.unit() - 0.5f, rng.unit() - 0.5f, rng.unit() - 0.5f};
		Vec3 b = a * Vec3{2.0f * rng.unit() - 1.0f, 2.0f * rng.unit() - 1.0f, 2.0f * rng.unit() - 1.0f};
		around.push_back(make_triangle(rng, a, -a, b));
	}
	for (size_t max_leaf_size : {1, 4}) {
		for (const auto* triangles : {&same, &around}) {
			std::vector<Ray> rays = random_rays(rng, bounds_of(*triangles), *triangles, 400);
			BVH_Triangles::Answer answer = judge::ask(BVH_Triangles{*triangles, max_leaf_size, rays});
			bool built = false;
			{
				INFO("when all centroids coincide no split can separate them: make a leaf or split by count, but "
				     "never recurse forever (handout §3.2)");
				built = check_structure(*triangles, max_leaf_size, answer);
			}
			if (!built) return;
			std::string report = Closest_Hits(*triangles).compare(answer.hits, rays);
			INFO(report);
			CHECK(report.empty());
		}
	}
}

TEST_CASE("BVH over a flat mesh (every box flat in z): structure and hits", "[id:t3.bvh.flat-mesh][task3][bvh][degenerate][fn:BVH::build][fn:BVH::hit][uses:BBox::hit]") {
	RNG rng(scene_seed(314));
	const int n = 24;
	std::vector<Triangle> grid = planar_grid(rng, n);

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
	Closest_Hits expected(grid);
	REQUIRE(expected.hitting(rays) > rays.size() / 2); // the grader's own rays must hit the grid, or nothing is tested
	for (size_t max_leaf_size : {1, 4}) {
		BVH_Triangles::Answer answer = judge::ask(BVH_Triangles{grid, max_leaf_size, rays});
		if (!check_structure(grid, max_leaf_size, answer)) return;
		INFO("a planar mesh has flat boxes everywhere: BBox::hit must accept enter == exit (handout §3.1); "
		     "max_leaf_size = "
		     << max_leaf_size);
		std::string report = expected.compare(answer.hits, rays);
		INFO(report);
		CHECK(report.empty());
	}
}

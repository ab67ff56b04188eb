// Task 3, handout §3.4: the tree is a good SAH tree (§3.2) and the traversal is front to back
// (§3.3), measured against an independent binned-SAH builder and an ideal traversal.
#include "bvh_oracle.h"
#include "bvh_test_scenes.h"
#include "call_counter.h"
#include "obj_loader.h"

#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

namespace {

// Allowed ratios to the oracle (handout §3.4).
constexpr double MAX_SAH_RATIO = 1.2;
constexpr double MAX_TESTS_RATIO = 1.5;

template<typename Primitive> void require_valid(const BVH<Primitive>& bvh, size_t max_leaf_size) {
	std::string problem = oracle::check_structure(bvh, max_leaf_size);
	INFO("BVH::build: " << problem << " (handout §3.2; the quality of the tree is measured only once its "
	                                  "structure is right)");
	REQUIRE(problem.empty());
}

void check_sah_cost(const std::string& scene, const std::vector<Triangle>& triangles) {
	for (size_t max_leaf_size : {1, 4}) {
		BVH<Triangle> bvh(std::vector<Triangle>(triangles), max_leaf_size);
		require_valid(bvh, max_leaf_size);
		double cost = oracle::sah_cost(oracle::tree_of(bvh), boxes_of(bvh.primitives));
		std::vector<BBox> boxes = boxes_of(triangles);
		double best = oracle::sah_cost(oracle::build_binned_sah(boxes, max_leaf_size), boxes);
		INFO(scene << " (" << triangles.size() << " triangles), max_leaf_size = " << max_leaf_size
		           << ": the SAH cost of your tree is " << cost << ", that of a binned-SAH tree " << best
		           << ", a ratio of " << cost / best << " (at most " << MAX_SAH_RATIO
		           << " allowed). Build with the surface area heuristic: bin the centroids into buckets on each "
		              "of the three axes, evaluate C = C_trav + S_A/S_N N_A + S_B/S_N N_B at every bucket boundary "
		              "and split at the cheapest; splitting at the median primitive is not enough "
		              "(handout §3.2, §3.4)");
		CHECK(cost <= MAX_SAH_RATIO * best);
	}
}

// Counts Instance::hit calls (framework-counted) made by `trace_all`.
template<typename F> uint64_t instance_tests(F&& trace_all) {
	Call_Counter calls;
	trace_all();
	return calls.instance_tests;
}

void check_primitive_tests(const std::string& scene, std::vector<Instance> instances, const std::vector<Ray>& rays) {
	std::vector<BBox> boxes;
	for (const Instance& instance : instances) boxes.push_back(instance.bbox());
	oracle::Tree best_tree = oracle::build_binned_sah(boxes, 1);

	BVH<Instance> bvh(std::vector<Instance>(instances), 1);
	require_valid(bvh, 1);
	oracle::Tree your_tree = oracle::tree_of(bvh);

	uint64_t yours = instance_tests([&] {
		for (const Ray& ray : rays) bvh.hit(ray);
	});
	uint64_t ideal_on_yours = instance_tests([&] {
		for (const Ray& ray : rays)
			oracle::traverse(your_tree, ray, [&](size_t i, const Ray& r) { return bvh.primitives[i].hit(r); });
	});
	uint64_t ideal = instance_tests([&] {
		for (const Ray& ray : rays)
			oracle::traverse(best_tree, ray, [&](size_t i, const Ray& r) { return instances[i].hit(r); });
	});
	double per_ray = double(yours) / rays.size(), ideal_per_ray = double(ideal) / rays.size();
	double traversal_ratio = double(yours) / std::max<double>(1.0, double(ideal_on_yours));
	double tree_ratio = double(ideal_on_yours) / std::max<double>(1.0, double(ideal));
	INFO(scene << " (" << instances.size() << " objects, " << rays.size() << " rays): your BVH::hit tests "
	           << per_ray << " objects per ray; an ideal front-to-back traversal of a binned-SAH tree tests "
	           << ideal_per_ray << ", a ratio of " << per_ray / ideal_per_ray << " (at most " << MAX_TESTS_RATIO
	           << " allowed).\n"
	           << "Of that ratio, your traversal accounts for " << traversal_ratio
	           << " (your BVH::hit against an ideal traversal of your own tree: visit the nearer child first and "
	              "skip a child whose box starts beyond the closest hit so far, handout §3.3) and your tree for "
	           << tree_ratio << " (ideal traversals of your tree and of a binned-SAH tree, handout §3.2).");
	CHECK(double(yours) <= MAX_TESTS_RATIO * double(ideal));
}

// Objects for the traversal test: one-triangle meshes and small spheres in a cube, placed at random.
std::vector<Instance> object_cloud(RNG& rng, size_t count) {
	std::vector<Instance> instances = triangle_instances(random_soup(rng, count / 2, 0.15f));
	while (instances.size() < count) {
		Vec3 centre = 2.0f * Vec3{rng.unit(), rng.unit(), rng.unit()} - 1.0f;
		Sphere sphere;
		sphere.radius = 0.03f + 0.06f * rng.unit();
		instances.emplace_back(sphere, glm::translate(Mat4{1.0f}, centre), 0u, uint32_t(instances.size()));
	}
	return instances;
}

std::vector<Triangle> load_mesh(const std::string& path) {
	INFO("grader self-check: the lab's meshes must load (run the grader from the repository root)");
	std::vector<Triangle> triangles;
	REQUIRE_NOTHROW(triangles = load_obj(path));
	return triangles;
}

} // namespace

TEST_CASE("BVH::build: SAH cost within 1.2x of a binned-SAH tree", "[task3][bvh][sah]") {
	RNG rng(321);
	check_sah_cost("clustered triangles with a few large ones", clustered_soup(rng));
	check_sah_cost("a random triangle soup", random_soup(rng, 4000, 0.05f));
	check_sah_cost("the bunny mesh", load_mesh("scenes/meshes/bunny_npm_lowres.obj"));
	check_sah_cost("the dragon mesh", load_mesh("scenes/meshes/dragon_vrip_res4.obj"));
}

TEST_CASE("BVH::hit: objects tested per ray within 1.5x of an ideal front-to-back traversal",
          "[task3][bvh][traversal]") {
	RNG rng(322);
	std::vector<Instance> cloud = object_cloud(rng, 4000);
	BBox box;
	for (const Instance& instance : cloud) box.enclose(instance.bbox());
	std::vector<Triangle> vertices_for_rays = random_soup(rng, 100, 0.06f);
	check_primitive_tests("a cloud of small triangles and spheres", cloud,
	                      random_rays(rng, box, vertices_for_rays, 20000));

	std::vector<Triangle> bunny = load_mesh("scenes/meshes/bunny_npm_lowres.obj");
	check_primitive_tests("the bunny, one object per triangle", triangle_instances(bunny),
	                      random_rays(rng, bounds_of(bunny), bunny, 20000));
}

// Task 3, handout §3.4: the tree is a good SAH tree (§3.2) and the traversal is front to back
// (§3.3), measured against the reference's binned-SAH tree (built here, in the judge) and an ideal
// traversal (tree_check.h: the primitives of the leaves a ray's segment up to its closest hit
// overlaps). The student's tree and hits come from the subject; the objects it tests are counted by
// the judge, which answers each test.
#include "bvh_test_scenes.h"
#include "judge.h"
#include "tree_check.h"

#include "lab_catch2.h"

#include <glm/gtc/matrix_transform.hpp>

#include <numeric>
#include <sstream>

using protocol::BVH_Instances;
using protocol::BVH_Triangles;

namespace {

// Allowed ratios to the reference (handout §3.4).
constexpr double MAX_SAH_RATIO = 1.2;
constexpr double MAX_TESTS_RATIO = 1.5;
// Rays per scene of the traversal test: each object tested is a question to the judge (about 40 µs).
constexpr size_t RAYS = 5000;

// The tree must keep the contract before its quality means anything.
bool valid(const protocol::Tree& tree, const std::vector<BBox>& boxes, size_t max_leaf_size) {
	std::string problem = task3::structure_problem(tree, boxes, max_leaf_size);
	INFO("BVH::build: " << problem << " (handout §3.2; the quality of the tree is measured only once its "
	                                  "structure is right)");
	CHECK(problem.empty());
	return problem.empty();
}

bool check_sah_cost(const std::string& scene, const std::vector<Triangle>& triangles) {
	for (size_t max_leaf_size : {1, 4}) {
		BVH_Triangles::Answer answer = judge::ask(BVH_Triangles{triangles, max_leaf_size, {}});
		if (answer.primitives.size() != triangles.size()) {
			FAIL_CHECK("BVH::build must keep every primitive exactly once (handout §3.2)");
			return false;
		}
		if (!valid(answer.tree, boxes_of(answer.primitives), max_leaf_size)) return false;
		double cost = task3::sah_cost(answer.tree, boxes_of(answer.primitives));
		BVH<Triangle> reference(std::vector<Triangle>(triangles), max_leaf_size);
		double best = task3::sah_cost(task3::tree_of(reference), boxes_of(reference.primitives));
		INFO(scene << " (" << triangles.size() << " triangles), max_leaf_size = " << max_leaf_size
		           << ": the SAH cost of your tree is " << cost << ", that of a binned-SAH tree " << best
		           << ", a ratio of " << cost / best << " (at most " << MAX_SAH_RATIO
		           << " allowed). Build with the surface area heuristic: bin the centroids into buckets on each "
		              "of the three axes, evaluate C = C_trav + S_A/S_N N_A + S_B/S_N N_B at every bucket boundary "
		              "and split at the cheapest; splitting at the median primitive is not enough "
		              "(handout §3.2, §3.4)");
		CHECK(cost <= MAX_SAH_RATIO * best);
		if (cost > MAX_SAH_RATIO * best) return false;
		std::ostringstream ratio;
		ratio.precision(3);
		ratio << cost / best;
		judge::key_figure("SAH cost of your tree / the reference's, " + scene + ", leaves of " +
		                      std::to_string(max_leaf_size),
		                  ratio.str());
	}
	return true;
}

void check_primitive_tests(const std::string& scene, const Scene& objects, const std::vector<Ray>& rays) {
	const std::vector<Instance>& instances = objects.bvh.primitives; // the decoded order: by index
	// Sorted through their positions: sorting the Instances themselves moves their std::variant
	// shapes, in which GCC 12 and 14 see members "maybe used uninitialized" (a false alarm).
	std::vector<size_t> order(instances.size());
	std::iota(order.begin(), order.end(), size_t(0));
	std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return instances[a].index < instances[b].index; });
	std::vector<Instance> by_index;
	by_index.reserve(instances.size());
	for (size_t i : order) by_index.push_back(instances[i]);
	std::vector<BBox> boxes;
	for (const Instance& object : by_index) boxes.push_back(object.bbox());

	// The subject has the boxes alone; each object its BVH::hit tests is a question to the judge,
	// answered with the object's real hit and counted here (protocol.h: BVH_Instances).
	uint64_t tests = 0;
	auto answer_object = [&](const std::string& payload) {
		auto question = wire::decode<protocol::Object_Question>(payload);
		if (question.object >= by_index.size()) {
			throw wire::Malformed("object " + std::to_string(question.object) + " of " + std::to_string(by_index.size()));
		}
		tests++;
		return wire::encode(by_index[question.object].hit(question.ray));
	};

	// The tree alone first: the count below means something only for a valid tree, and an invalid
	// one (the starter's single leaf) would make the subject test every object for every ray.
	auto valid_tree = [&](const BVH_Instances::Answer& answer) {
		for (uint32_t index : answer.order) {
			if (index >= by_index.size()) {
				FAIL_CHECK("BVH::build returned an object that was not given to it (handout §3.2)");
				return false;
			}
		}
		std::vector<BBox> your_boxes;
		for (uint32_t index : answer.order) your_boxes.push_back(boxes[index]);
		return valid(answer.tree, your_boxes, 1);
	};
	if (!valid_tree(judge::ask(BVH_Instances{boxes, 1, {}}, answer_object))) return;
	tests = 0;
	BVH_Instances::Answer answer = judge::ask(BVH_Instances{boxes, 1, rays}, answer_object);
	if (!valid_tree(answer)) return; // (a build that differs from the first)

	BVH<Instance> reference(std::vector<Instance>(by_index), 1);
	protocol::Tree best_tree = task3::tree_of(reference);
	uint64_t ideal_on_yours = 0, ideal = 0, wrong = 0;
	for (size_t r = 0; r < rays.size(); r++) {
		Trace hit = reference.hit(rays[r]);
		float closest = hit.hit ? hit.distance : INF_F;
		wrong += answer.hits[r].hit != hit.hit || (hit.hit && answer.hits[r].distance != hit.distance);
		ideal_on_yours += task3::ideal_tests(answer.tree, rays[r], closest);
		ideal += task3::ideal_tests(best_tree, rays[r], closest);
	}
	// A count means something only for a traversal that finds every closest hit.
	if (wrong > 0) {
		FAIL_CHECK("BVH::hit missed the closest hit of " << wrong << " of " << rays.size() << " rays through " << scene
		           << " (handout §3.3: test every leaf whose box the ray's segment up to the closest hit so far "
		              "overlaps, and keep the closest hit)");
		return;
	}
	uint64_t yours = tests;
	double per_ray = double(yours) / rays.size(), ideal_per_ray = double(ideal) / rays.size();
	double traversal_ratio = double(yours) / std::max<double>(1.0, double(ideal_on_yours));
	double tree_ratio = double(ideal_on_yours) / std::max<double>(1.0, double(ideal));
	INFO(scene << " (" << by_index.size() << " objects, " << rays.size() << " rays): your BVH::hit tests "
	           << per_ray << " objects per ray; an ideal front-to-back traversal of a binned-SAH tree tests "
	           << ideal_per_ray << ", a ratio of " << per_ray / ideal_per_ray << " (at most " << MAX_TESTS_RATIO
	           << " allowed).\n"
	           << "Of that ratio, your traversal accounts for " << traversal_ratio
	           << " (your BVH::hit against an ideal traversal of your own tree: visit the nearer child first and "
	              "skip a child whose box starts beyond the closest hit so far, handout §3.3) and your tree for "
	           << tree_ratio << " (ideal traversals of your tree and of a binned-SAH tree, handout §3.2).");
	CHECK(double(yours) <= MAX_TESTS_RATIO * double(ideal));
	std::ostringstream ratio;
	ratio.precision(3);
	ratio << per_ray / ideal_per_ray;
	judge::key_figure("objects tested per ray / an ideal traversal of the reference's tree, " + scene, ratio.str());
}

// A scene of objects for the traversal test: one-triangle meshes and small spheres in a cube, placed
// at random (committed, so that its objects are in its top-level BVH).
Scene object_cloud(RNG& rng, size_t count) {
	Scene scene;
	scene.materials.push_back(Material{});
	for (const Triangle& t : random_soup(rng, count / 2, 0.15f)) {
		scene.objects.emplace_back(Tri_Mesh({t}, 1), Mat4{1.0f}, 0u, uint32_t(scene.objects.size()));
	}
	while (scene.objects.size() < count) {
		Vec3 centre = 2.0f * Vec3{rng.unit(), rng.unit(), rng.unit()} - 1.0f;
		Sphere sphere;
		sphere.radius = 0.03f + 0.06f * rng.unit();
		scene.objects.emplace_back(sphere, glm::translate(Mat4{1.0f}, centre), 0u, uint32_t(scene.objects.size()));
	}
	scene.commit();
	return scene;
}

Scene triangle_objects(const std::vector<Triangle>& triangles) {
	Scene scene;
	scene.materials.push_back(Material{});
	for (size_t i = 0; i < triangles.size(); i++) scene.objects.emplace_back(Tri_Mesh({triangles[i]}, 1), Mat4{1.0f}, 0u, uint32_t(i));
	scene.commit();
	return scene;
}

} // namespace

TEST_CASE("BVH::build: SAH cost within 1.2x of a binned-SAH tree", "[id:t3.bvh.sah-cost][task3][bvh][sah][fn:BVH::build]") {
	RNG rng(scene_seed(321));
	check_sah_cost("clustered triangles with a few large ones", clustered_soup(rng)) &&
		check_sah_cost("a random triangle soup", random_soup(rng, 4000, 0.05f)) &&
		check_sah_cost("the bunny mesh", load_placed_mesh("scenes/meshes/bunny_npm_lowres.obj")) &&
		check_sah_cost("the dragon mesh", load_placed_mesh("scenes/meshes/dragon_vrip_res4.obj"));
}

TEST_CASE("BVH::hit: objects tested per ray within 1.5x of an ideal front-to-back traversal",
          "[id:t3.bvh.traversal-cost][task3][bvh][traversal][fn:BVH::hit][uses:BBox::hit][uses:BVH::build]") {
	RNG rng(scene_seed(322));
	Scene cloud = object_cloud(rng, 4000);
	std::vector<Triangle> vertices_for_rays = random_soup(rng, 100, 0.06f);
	check_primitive_tests("a cloud of small triangles and spheres", cloud,
	                      random_rays(rng, cloud.bvh.bbox(), vertices_for_rays, RAYS));

	std::vector<Triangle> bunny = load_placed_mesh("scenes/meshes/bunny_npm_lowres.obj");
	check_primitive_tests("the bunny, one object per triangle", triangle_objects(bunny),
	                      random_rays(rng, bounds_of(bunny), bunny, RAYS));
}

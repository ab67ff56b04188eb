// Task 3 grader, reference image: the eye view of the graded bunny scene (3 674 triangles) rendered
// through the student's BVH. A BVH changes only the speed, never the picture, so the image must match
// the reference (framework/film/image_compare.h), and the bunny's BVH must be a real hierarchy: the
// starter code's single leaf is correct, but it is not the task.
#include "graded_images.h"
#include "judge.h"
#include "student_renders.h"

#include "lab_catch2.h"

TEST_CASE("the graded scene eye_bunny renders through the BVH like its reference image",
          "[id:t3.image.eye-bunny][task3][image][statistical:2][uses:BBox::hit][uses:BVH::build][uses:BVH::hit]") {
	Image_Test test;
	test.name = "eye_bunny";
	test.hint = "Missing or wrong surfaces: the traversal skipped a node it must visit, or kept a farther hit (handout "
	            "§3.3); the box test must accept rays that start inside and flat boxes (handout §3.1).";
	test.if_failed = {{"BBox::hit", "which nodes a ray enters: flat boxes, rays starting inside, zero direction "
	                                "components (handout §3.1)."},
	                  {"BVH::build", "the tree's layout (handout §3.2)."},
	                  {"BVH::hit", "which hit is the closest: every child the ray enters before the closest hit so "
	                               "far (handout §3.3)."}};
	test.if_noisy = "A traversal that answers the same ray differently from call to call (state kept between calls, "
	                "uninitialized values) makes the eye view noisy (handout §3.3).";
	check_renders_like_reference(test);
}

TEST_CASE("the bunny of the graded scene gets a BVH of more than one node", "[id:t3.image.bvh-split][task3][image][fn:BVH::build]") {
	Scene scene = load_graded(graded_scene("eye_bunny"));
	const Tri_Mesh* bunny = nullptr;
	for (const Instance& object : scene.bvh.primitives) {
		auto mesh = std::get_if<Tri_Mesh>(&object.shape);
		if (mesh && (!bunny || mesh->triangle_count() > bunny->triangle_count())) bunny = mesh;
	}
	REQUIRE(bunny != nullptr); // the graded scene holds the bunny
	protocol::BVH_Triangles::Answer answer = judge::ask(protocol::BVH_Triangles{bunny->bvh.primitives, 4, {}});
	INFO("the bunny's BVH has " << answer.tree.nodes.size() << " node(s) for " << bunny->triangle_count()
	     << " triangles: build must split the primitives with the SAH until the leaves are small (handout §3.2)");
	CHECK(answer.tree.nodes.size() > 1);
}

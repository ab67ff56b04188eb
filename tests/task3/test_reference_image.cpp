// Task 3 grader, reference image: the eye view of the graded bunny scene (3 674 triangles) rendered
// through the student's BVH. A BVH changes only the speed, never the picture, so the image must match
// the reference (tests/support/image_compare.h), and the bunny's BVH must be a real hierarchy: the
// starter code's single leaf is correct, but it is not the task.
#include "graded_images.h"
#include "student_renders.h"
#include "scene_loader.h"
#include "tri_mesh.h"

#include <catch2/catch.hpp>

TEST_CASE("the graded scene eye_bunny renders through the BVH like its reference image",
          "[task3][image][statistical]") {
	check_renders_like_reference("eye_bunny",
	                             "Missing or wrong surfaces: the traversal skipped a node it must visit, or kept a farther hit "
	                             "(handout §3.3); the box test must accept rays that start inside and flat boxes (handout §3.1). "
	                             "Render it: ./lab render-student scenes/graded/eye_bunny.json --view eye");
}

TEST_CASE("the bunny of the graded scene gets a BVH of more than one node", "[task3][image]") {
	Scene scene = load_scene(graded_scene_file("eye_bunny"));
	size_t largest = 0;
	for (const Instance& object : scene.bvh.primitives) {
		if (auto mesh = std::get_if<Tri_Mesh>(&object.shape)) largest = std::max(largest, mesh->bvh.nodes.size());
	}
	INFO("the bunny's BVH has " << largest << " node(s) for 3 674 triangles: build must split the primitives "
	     "with the SAH until the leaves are small (handout §3.2)");
	CHECK(largest > 1);
}

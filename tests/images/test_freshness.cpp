// The stored references (scenes/graded/references/) must still be what the reference renderer
// produces: each graded scene, rendered by the reference at the graders' samples and seed, passes
// the image comparison (framework/film/image_compare.h). If this fails after a change to reference/
// or a graded scene, the change is biased or the references are stale: `./lab references`.
#include "graded_images.h"

#include "lab_catch2.h"

TEST_CASE("every stored reference image matches the reference renderer within its noise", "[images]") {
	for (const Graded_Scene& scene : graded_scenes()) {
		Reference_Check check = check_against_reference(scene);
		INFO(scene.name << ": " << check.comparison.message);
		CHECK(check.non_finite == 0);
		CHECK(check.comparison.pass);
	}
}

// Task 6 grader, reference image: the Cornell box with two spheres and a small, bright light, path
// traced with the mixture of BSDF and light sampling.
// The render is compared with the stored reference pixel by pixel, by a z-test that knows the noise
// of both (framework/film/image_compare.h); scenes/graded/references/ holds the reference.
#include "student_renders.h"

#include "lab_catch2.h"

TEST_CASE("the graded scene cornell_small_light renders like its reference image",
          "[id:t6.image.cornell-small-light][estimate][task6][image][statistical:2][uses:sample_incoming]") {
	Image_Test test;
	test.name = "cornell_small_light";
	test.hint = "The mixture's pdf must be 1/2 p_bsdf + 1/2 p_lights for EVERY direction, whichever strategy drew it "
	            "(handout §6.2).";
	test.if_failed = {{"sample_incoming", "the mixture's directions and their density (handout §6.2, §6.3)."}};
	test.if_noisy = "Under a small light, light sampling is what keeps the noise down: a fair coin between the "
	                "strategies, and the mixture's pdf for every direction, never one strategy's alone (handout §6.1, "
	                "§6.2).";
	check_renders_like_reference(test);
}

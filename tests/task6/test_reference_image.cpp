// Task 6 grader, reference image: the Cornell box with two spheres and a small, bright light, path
// traced with the mixture of BSDF and light sampling.
// The render is compared with the stored reference pixel by pixel, by a z-test that knows the noise
// of both (framework/image_compare.h); scenes/graded/references/ holds the reference.
#include "student_renders.h"

#include <catch2/catch.hpp>

TEST_CASE("the graded scene cornell_small_light renders like its reference image",
          "[task6][image][statistical][uses:sample_incoming]") {
	check_renders_like_reference(
		"cornell_small_light",
		"The mixture's pdf must be 1/2 p_bsdf + 1/2 p_lights for EVERY direction, whichever strategy drew it (handout "
		"§6.2).",
		{{"sample_incoming", "the mixture's directions and their density (handout §6.2, §6.3)."}});
}

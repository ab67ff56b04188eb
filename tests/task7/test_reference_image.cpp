// Task 7 grader, reference image: a diffuse sphere on a floor under an overcast HDR sky, with
// environment importance sampling.
// The render is compared with the stored reference pixel by pixel, by a z-test that knows the noise
// of both (tests/support/image_compare.h); scenes/graded/references/ holds the reference.
#include "student_renders.h"

#include <catch2/catch.hpp>

TEST_CASE("the graded scene env_overcast renders like its reference image",
          "[task7][image][statistical]") {
	check_renders_like_reference("env_overcast",
	                             "Check that Env_Map::pdf converts the density over the image to solid angle with the "
	                             "Jacobian 2 pi^2 sin(theta) (handout §7.4) and agrees with sample. Render it: ./lab "
	                             "render-student scenes/graded/env_overcast.json");
}

// Task 7 grader, reference image: a diffuse sphere on a floor under an overcast HDR sky, with
// environment importance sampling.
// The render is compared with the stored reference pixel by pixel, by a z-test that knows the noise
// of both (framework/film/image_compare.h); scenes/graded/references/ holds the reference.
#include "student_renders.h"

#include "lab_catch2.h"

TEST_CASE("the graded scene env_overcast renders like its reference image",
          "[id:t7.image.env-overcast][estimate][task7][image][statistical:2][uses:Env_Map::sample][uses:Env_Map::pdf][uses:Env_Map::evaluate]") {
	Image_Test test;
	test.name = "env_overcast";
	test.hint = "Check that Env_Map::pdf converts the density over the image to solid angle with the Jacobian 2 pi^2 "
	            "sin(theta) (handout §7.4) and agrees with sample.";
	test.if_failed = {{"direction_to_uv", "where in the map a direction looks (handout §7.1)."},
	                  {"uv_to_direction", "the directions of sampled map points (handout §7.1)."},
	                  {"Env_Map::evaluate", "the sky's radiance, interpolated between texel centres (handout §7.2)."},
	                  {"Uniform::sample", "uniform directions (handout §7.3)."},
	                  {"Image (tables)", "the texels' probabilities, luminance times sin(theta) (handout §7.4)."},
	                  {"Image::sample", "importance-sampled directions (handout §7.4)."},
	                  {"Image::pdf", "the density with the Jacobian 2 pi^2 sin(theta) (handout §7.4)."},
	                  {"Env_Map::sample", "which sampler the map uses (handout §7.5)."},
	                  {"Env_Map::pdf", "which density the map reports (handout §7.5)."}};
	test.if_noisy = "Weights L / pdf grow without bound where the pdf is too small for the light: the table must follow "
	                "luminance * sin(theta) over each texel's whole bilinear footprint, and pdf must be what sample "
	                "draws (handout §7.4).";
	check_renders_like_reference(test);
}

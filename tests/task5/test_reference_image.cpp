// Task 5 grader, reference image: a large glass ball and a small mirror ball under an overcast sky,
// path traced, 64 samples per pixel. Near the glass ball's rim Fresnel reflection shows the sky and
// refraction the ground.
// The render is compared with the stored reference pixel by pixel, by a z-test that knows the noise
// of both (framework/film/image_compare.h); scenes/graded/references/ holds the reference.
#include "student_renders.h"

#include "lab_catch2.h"

TEST_CASE("the graded scene glass_balls renders like its reference image",
          "[id:t5.image.glass-balls][estimate][task5][image][statistical:2][uses:Mirror::scatter][uses:Glass::scatter]") {
	Image_Test test;
	test.name = "glass_balls";
	test.hint = "The glass ball must both reflect (with probability F) and refract (handout §5.2, §5.3), the mirror "
	            "reflect about the normal (handout §5.1).";
	test.if_failed = {{"reflect", "the mirror's and the glass's reflections (handout §5.1)."},
	                  {"refract", "the glass's refractions, Snell's law from both sides (handout §5.2)."},
	                  {"fresnel", "how often the glass reflects (handout §5.3)."},
	                  {"Mirror::scatter", "the mirror ball (handout §5.4)."},
	                  {"Glass::scatter", "the glass ball: reflect with probability F, else refract (handout §5.4)."}};
	test.if_noisy = "A glass sample weighs exactly the reflectance or the transmittance: choosing by F and weighting "
	                "by 1 / F or 1 / (1 - F) as well makes fireflies (handout §5.4).";
	check_renders_like_reference(test);
}

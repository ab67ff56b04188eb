// Task 4 grader, reference image: the diffuse Cornell box, path traced, 64 samples per pixel, at
// most 5 bounces.
// The render is compared with the stored reference pixel by pixel, by a z-test that knows the noise
// of both (framework/film/image_compare.h); scenes/graded/references/ holds the reference.
#include "student_renders.h"

#include "lab_catch2.h"

TEST_CASE("the graded scene cornell_diffuse renders like its reference image",
          "[id:t4.image.cornell-diffuse][estimate][task4][image][statistical:2][uses:shade][uses:Lambertian::scatter][uses:Lambertian::evaluate][uses:Lambertian::pdf]") {
	Image_Test test;
	test.name = "cornell_diffuse";
	test.hint = "Too dark or too bright: check the estimator f * |cos| / pdf (handout §4.2) and that the Lambertian "
	            "BSDF, its sampling and its pdf agree (handout §4.1).";
	test.if_failed = {
		{"Lambertian::evaluate", "the BSDF's value albedo / pi (handout §4.1)."},
		{"Lambertian::pdf", "the density |cos theta| / pi the estimator divides by (handout §4.1)."},
		{"Lambertian::scatter", "the cosine-weighted directions (handout §4.1)."},
		{"shade", "the estimator: emission plus f |cos| / pdf times the next ray's radiance, and where the next ray "
		          "starts (spawn_ray, handout §4.2)."}};
	test.if_noisy = "Look for weights that can grow without bound: a division by a small pdf or cosine (the weight is "
	                "f |cos| / pdf, handout §4.2), and for a Russian roulette that cuts more often than the albedo "
	                "says (handout §4.3).";
	check_renders_like_reference(test);
}

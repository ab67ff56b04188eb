// Task 1 grader, reference image: the eye view (albedo * |cos| at the first hit) of a bunny, a
// sphere and a floor, 16 jittered samples per pixel.
// The render is compared with the stored reference pixel by pixel, by a z-test that knows the noise
// of both (framework/film/image_compare.h); scenes/graded/references/ holds the reference.
#include "student_renders.h"

#include "lab_catch2.h"

TEST_CASE("the graded scene eye_bunny renders like its reference image",
          "[id:t1.image.eye-bunny][estimate][task1][image][statistical:2][uses:generate_ray][uses:trace_pixel]") {
	Image_Test test;
	test.name = "eye_bunny";
	test.hint = "If the picture is shifted, flipped or stretched, look at generate_ray (handout §1.2); if edges are too "
	            "sharp or too soft, at the random point in the pixel of trace_pixel (handout §1.3).";
	test.if_failed = {
		{"generate_ray", "the camera rays: a shifted, flipped or stretched picture comes from them (handout §1.2)."},
		{"trace_pixel", "where in the pixel the samples fall: edges too sharp or too soft (handout §1.3)."}};
	test.if_noisy = "In the eye view only the point within the pixel varies from sample to sample: each sample must "
	                "be trace(rng, ray) of one ray through a point of ITS pixel, (x + u1, y + u2) (handout §1.3).";
	check_renders_like_reference(test);
}

// Task 2 grader, reference image: the eye view (albedo * |cos| at the first hit) of a smooth-shaded
// bunny (triangles), a sphere and a floor: which surface is hit first, and its normal's direction.
// The render is compared with the stored reference pixel by pixel, by a z-test that knows the noise
// of both (framework/film/image_compare.h); scenes/graded/references/ holds the reference.
#include "student_renders.h"

#include "lab_catch2.h"

TEST_CASE("the graded scene eye_bunny renders like its reference image",
          "[id:t2.image.eye-bunny][task2][image][statistical:2][uses:Triangle::hit][uses:Sphere::hit]") {
	Image_Test test;
	test.name = "eye_bunny";
	test.hint = "Wrong shading on the sphere or the bunny: check that hit normals point outwards, that the barycentric "
	            "interpolation of vertex normals uses (1 - u - v, u, v) (handout §2.1, §2.2); missing objects: check "
	            "the distance bounds (handout §2.3).";
	test.if_failed = {{"Triangle::hit", "the bunny's and the floor's hits and their interpolated normals (handout §2.1)."},
	                  {"Sphere::hit", "the ball's hits and its outward normals (handout §2.2)."}};
	test.if_noisy = "A hit routine that answers the same ray differently from call to call (uninitialized values, "
	                "a NaN normal) makes the eye view noisy (handout §2.1, §2.2).";
	check_renders_like_reference(test);
}

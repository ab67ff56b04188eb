// Calibration of the image comparison: a correct render must pass whatever its seed. The reference
// renders each graded scene with 20 seeds other than the graders', the references' and those whose
// outliers the references count (graded_images.h), and all 20 must pass; the comparison's
// false-failure rate per image is at most α = 0.01 by design (image_compare.h; measured over 100
// seeds per scene: 0 to 1 in 100), so a failure here means the variances, the outlier counts or
// the thresholds are wrong.
#include "graded_images.h"

#include "lab_catch2.h"

namespace {
constexpr uint64_t FIRST_SEED = 100, SEEDS = 20;
} // namespace

TEST_CASE("the reference passes the image comparison with 20 other seeds", "[images][calibration]") {
	for (const Graded_Scene& scene : graded_scenes()) {
		size_t passed = 0;
		for (uint64_t seed = FIRST_SEED; seed < FIRST_SEED + SEEDS; seed++) {
			Reference_Check check = check_against_reference(scene, seed);
			if (check.comparison.pass) passed++;
			else UNSCOPED_INFO(scene.name << ", seed " << seed << ": " << check.comparison.message);
		}
		INFO(scene.name << ": " << passed << " of " << SEEDS << " seeds pass");
		CHECK(passed == SEEDS);
	}
}

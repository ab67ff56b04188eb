// Calibration of the image comparison: a correct render must pass whatever its seed. The reference
// renders each graded scene with 20 seeds other than the graders' and the references', and all 20
// must pass; the comparison's false-failure rate per image is far below 1/20 by design (Šidák at
// α = 0.01 and 0.25% of the tests allowed to fail), so a single failure here means the variances
// or the threshold are wrong.
#include "graded_images.h"

#include <catch2/catch.hpp>

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

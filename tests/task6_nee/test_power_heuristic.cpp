// Grader of task 6's optional extension, part 1: power_heuristic (handout §6.5).
#include "student_calls.h"

#include "lab_catch2.h"

#include <cmath>

TEST_CASE("power_heuristic is pdf_f^2 / (pdf_f^2 + pdf_g^2)", "[id:t6nee.power.formula][task6_nee][fn:power_heuristic]") {
	const std::vector<Vec2> pairs{{1.0f, 1.0f}, {3.0f, 1.0f}, {1.0f, 3.0f}, {2.0f, 0.0f}, {0.5f, 0.25f}};
	const std::vector<float> expected{0.5f, 0.9f, 0.1f, 1.0f, 0.8f};
	std::vector<float> weights = student_power_heuristic(pairs);
	for (size_t i = 0; i < pairs.size(); i++) {
		INFO("power_heuristic(" << pairs[i].x << ", " << pairs[i].y << ") = " << weights[i] << ", expected "
		                        << expected[i] << " (handout §6.5)");
		CHECK(weights[i] == Approx(expected[i]).epsilon(1e-6));
	}
}

TEST_CASE("power_heuristic gives 0 to a strategy that cannot draw the direction", "[id:t6nee.power.zero-density][task6_nee][fn:power_heuristic]") {
	const std::vector<Vec2> pairs{{0.0f, 0.0f}, {0.0f, 1.0f}, {0.0f, 1e6f}};
	std::vector<float> weights = student_power_heuristic(pairs);
	for (size_t i = 0; i < pairs.size(); i++) {
		INFO("power_heuristic(0, " << pairs[i].y << ") = " << weights[i]
		                           << ": a density of 0 means the strategy never draws this direction, so its weight "
		                              "is 0, never NaN (handout §6.5)");
		CHECK(weights[i] == 0.0f);
	}
}

TEST_CASE("the weights of the two strategies add up to 1, for densities large and small",
          "[id:t6nee.power.sum-to-one][task6_nee][fn:power_heuristic]") {
	// Squares of densities near a light's silhouette (1e20 and more) overflow a float, squares of
	// tiny ones underflow to 0: a weight must stay finite and the pair must still sum to 1.
	std::vector<Vec2> pairs; // each (f, g) followed by (g, f)
	for (float f : {1e-30f, 1e-3f, 0.3f, 7.0f, 1e5f, 1e25f}) {
		for (float g : {1e-30f, 2e-3f, 0.3f, 40.0f, 1e25f}) {
			pairs.push_back({f, g});
			pairs.push_back({g, f});
		}
	}
	std::vector<float> weights = student_power_heuristic(pairs);
	for (size_t i = 0; i < pairs.size(); i += 2) {
		float a = weights[i], b = weights[i + 1];
		INFO("power_heuristic(" << pairs[i].x << ", " << pairs[i].y << ") = " << a << ", power_heuristic("
		                        << pairs[i].y << ", " << pairs[i].x << ") = " << b
		                        << " (handout §6.5: divide before squaring)");
		REQUIRE(std::isfinite(a));
		REQUIRE(a >= 0.0f);
		CHECK(a + b == Approx(1.0f).epsilon(1e-5));
	}
}

#pragma once
// Statistics for graders. Every random test uses a fixed seed and a threshold derived from the
// test's own significance level, corrected for the number of tests that share it (Šidák).
#include "significance.h" // sidak, normal_cdf, normal_quantile, two_sided_z, gamma_q, Poisson

#include <cstddef>
#include <cstdint>
#include <vector>

namespace stats {

struct Chi2_Result {
	double statistic = 0.0;
	size_t dof = 0;
	double p_value = 1.0;
	size_t pooled_cells = 0; // cells merged because their expected count was below the minimum
	// Samples that landed in cells whose expected count is 0: always a failure.
	double observed_in_impossible_cells = 0.0;
};

// Pearson's chi-square goodness-of-fit test of observed counts against expected counts (same
// total). Cells with expected count below `min_expected` are pooled (sorted by expected count and
// merged until each pool reaches the minimum), as in pbrt-v4 and Mitsuba 3.
Chi2_Result chi2_test(const std::vector<double>& observed, const std::vector<double>& expected,
                      double min_expected = 5.0);

// Two-sided binomial test by the normal approximation: z of observing `successes` in `trials`
// when the success probability is p.
double binomial_z(size_t successes, size_t trials, double p);

} // namespace stats

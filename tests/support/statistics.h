#pragma once
// Statistics for graders. Every random test uses a fixed seed and a threshold derived from the
// test's own significance level, corrected for the number of tests that share it (Šidák).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace stats {

// Šidák correction: the per-test significance that keeps the chance of ANY false failure among
// `tests` independent tests at `alpha`: 1 - (1 - alpha)^(1 / tests).
double sidak(double alpha, size_t tests);

// Standard normal distribution: cdf Phi(z) and the quantile Phi^-1(p).
double normal_cdf(double z);
double normal_quantile(double p);

// The |z| above which a two-sided z-test at significance alpha rejects.
double two_sided_z(double alpha);

// Regularized upper incomplete gamma function Q(a, x) = Gamma(a, x) / Gamma(a).
double gamma_q(double a, double x);

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

// P(X >= count) for X ~ Poisson(lambda).
double poisson_upper_tail(double lambda, uint64_t count);

// Garwood's (1936) upper confidence limit of a Poisson mean from one observed count: the lambda
// with P(Poisson(lambda) <= count) = 1 - confidence.
double poisson_upper_limit(uint64_t count, double confidence);

// Two-sided binomial test by the normal approximation: z of observing `successes` in `trials`
// when the success probability is p.
double binomial_z(size_t successes, size_t trials, double p);

} // namespace stats

#pragma once
// Significance levels of z-tests, shared by the image comparison (image_compare.h) and the
// graders' statistics (tests/support/statistics.h).
#include <cstddef>

namespace stats {

// Šidák correction: the per-test significance that keeps the chance of ANY false failure among
// `tests` independent tests at `alpha`: 1 - (1 - alpha)^(1 / tests).
double sidak(double alpha, size_t tests);

// Standard normal distribution: cdf Phi(z) and the quantile Phi^-1(p).
double normal_cdf(double z);
double normal_quantile(double p);

// The |z| above which a two-sided z-test at significance alpha rejects.
double two_sided_z(double alpha);

} // namespace stats

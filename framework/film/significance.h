#pragma once
// Significance levels of z-tests, shared by the image comparison (image_compare.h) and the
// graders' statistics (tests/support/statistics.h).
#include <cstddef>
#include <cstdint>

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

// P(X >= count) for X ~ Poisson(lambda).
double poisson_upper_tail(double lambda, uint64_t count);

// Garwood's (1936) upper confidence limit of a Poisson mean from one observed count: the lambda
// with P(Poisson(lambda) <= count) = 1 - confidence.
double poisson_upper_limit(uint64_t count, double confidence);

} // namespace stats

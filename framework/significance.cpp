#include "significance.h"

#include <cmath>
#include <stdexcept>

namespace stats {

double sidak(double alpha, size_t tests) {
	return 1.0 - std::pow(1.0 - alpha, 1.0 / double(tests));
}

double normal_cdf(double z) {
	return 0.5 * std::erfc(-z / std::sqrt(2.0));
}

double normal_quantile(double p) {
	if (!(p > 0.0 && p < 1.0)) throw std::domain_error("normal_quantile: p must lie in (0, 1)");
	// Bisection on the cdf: slow but exact to double precision, and graders call it rarely.
	double lo = -40.0, hi = 40.0;
	for (int i = 0; i < 200; i++) {
		double mid = 0.5 * (lo + hi);
		(normal_cdf(mid) < p ? lo : hi) = mid;
	}
	return 0.5 * (lo + hi);
}

double two_sided_z(double alpha) {
	return normal_quantile(1.0 - 0.5 * alpha);
}

} // namespace stats

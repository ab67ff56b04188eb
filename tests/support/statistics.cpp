#include "statistics.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace stats {

Chi2_Result chi2_test(const std::vector<double>& observed, const std::vector<double>& expected, double min_expected) {
	if (observed.size() != expected.size()) throw std::invalid_argument("chi2_test: size mismatch");
	Chi2_Result result;
	std::vector<size_t> order(expected.size());
	std::iota(order.begin(), order.end(), size_t(0));
	std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return expected[a] < expected[b]; });

	double pool_observed = 0.0, pool_expected = 0.0;
	size_t cells = 0;
	for (size_t i : order) {
		if (expected[i] == 0.0) {
			result.observed_in_impossible_cells += observed[i];
			continue;
		}
		if (expected[i] < min_expected || pool_expected > 0.0) {
			// Accumulate small cells (in ascending order) until the pool is large enough.
			pool_observed += observed[i];
			pool_expected += expected[i];
			result.pooled_cells++;
			if (pool_expected < min_expected) continue;
			result.statistic += (pool_observed - pool_expected) * (pool_observed - pool_expected) / pool_expected;
			pool_observed = pool_expected = 0.0;
			cells++;
			continue;
		}
		double diff = observed[i] - expected[i];
		result.statistic += diff * diff / expected[i];
		cells++;
	}
	if (pool_expected > 0.0) { // a last, still small pool
		result.statistic += (pool_observed - pool_expected) * (pool_observed - pool_expected) / pool_expected;
		cells++;
	}
	result.dof = cells > 1 ? cells - 1 : 0;
	result.p_value = result.dof > 0 ? gamma_q(0.5 * double(result.dof), 0.5 * result.statistic) : 1.0;
	return result;
}


double binomial_z(size_t successes, size_t trials, double p) {
	double mean = double(trials) * p;
	double sd = std::sqrt(double(trials) * p * (1.0 - p));
	return sd > 0.0 ? (double(successes) - mean) / sd : (double(successes) == mean ? 0.0 : INFINITY);
}

} // namespace stats

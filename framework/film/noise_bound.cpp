#include "noise_bound.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace {
// Var(s²) of n samples (noise_bound.h). At least 2 σ⁴ / (n (n - 1)), its value for a symmetric
// two-point law (kurtosis 1, the smallest there is): estimated moments may fall below it.
double variance_of_variance(double variance, double fourth, double n) {
	double sigma4 = variance * variance;
	return std::max((fourth - (n - 3.0) / (n - 1.0) * sigma4) / n, 2.0 * sigma4 / (n * (n - 1.0)));
}
} // namespace

void Variance_Sum::add(double reference_variance, double reference_fourth, double n, double n_reference,
                       double rounding_sd) {
	if (!(n >= 2.0 && n_reference >= 2.0)) throw std::invalid_argument("Variance_Sum: a variance needs two samples");
	expected += reference_variance;
	variance += variance_of_variance(reference_variance, reference_fourth, n) +
	            variance_of_variance(reference_variance, reference_fourth, n_reference);
	rounding += rounding_sd * rounding_sd;
}

Variance_Sum combine_channels(const std::array<Variance_Sum, 3>& channels) {
	Variance_Sum all;
	double sd = 0.0;
	for (const Variance_Sum& c : channels) {
		all.expected += c.expected;
		all.rounding += c.rounding;
		sd += std::sqrt(c.variance);
	}
	all.variance = sd * sd;
	return all;
}

Noise_Check check_noise(double submitted, const Variance_Sum& reference, double alpha) {
	Noise_Check check;
	check.alpha = alpha;
	check.submitted = submitted;
	check.reference = reference.expected;
	double t = std::sqrt(reference.variance * (1.0 - alpha) / alpha);
	check.allowed = reference.expected + t + reference.rounding;
	check.pass = submitted <= check.allowed; // false for NaN
	check.ratio = reference.expected > 0.0 ? submitted / reference.expected : submitted > 0.0 ? INFINITY : 1.0;
	check.k = reference.expected > 0.0 ? check.allowed / reference.expected : INFINITY;
	return check;
}

std::string describe(const Noise_Check& c, const std::string& what) {
	std::ostringstream out;
	out.precision(3);
	out << "the per-sample variance of " << what << " is ";
	if (c.reference > 0.0) {
		out << c.ratio << " times the reference's (" << c.submitted << " against " << c.reference
		    << "); a correct solution stays below " << c.k << " times";
	} else {
		out << c.submitted << " where the reference's is 0 (allowed for float rounding: " << c.allowed << ")";
	}
	out << " (one-sided bound at alpha = " << c.alpha << ")";
	return out.str();
}

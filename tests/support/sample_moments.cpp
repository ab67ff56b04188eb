#include "sample_moments.h"

#include <cmath>

double Sample_Moments::standard_error() const {
	return std::sqrt(variance / double(n));
}

double Sample_Moments::variance_of_variance() const {
	return (fourth - variance * variance) / double(n);
}

Sample_Moments moments(const std::vector<double>& samples) {
	Sample_Moments m;
	m.n = samples.size();
	for (double x : samples) m.mean += x / double(m.n);
	double m2 = 0.0, m4 = 0.0;
	for (double x : samples) {
		double d = (x - m.mean) * (x - m.mean);
		m2 += d, m4 += d * d;
	}
	m.variance = m2 / double(m.n - 1);
	m.fourth = m4 / double(m.n);
	return m;
}

double standard_error(const Sample_Moments& reference, size_t n) {
	return std::sqrt(reference.variance / double(n));
}

Paired_Noise compare_noise(const std::array<std::vector<double>, 3>& submission,
                           const std::array<std::vector<double>, 3>& reference, double alpha,
                           const std::array<double, 3>& rounding_sd) {
	std::vector<double> s(NOISE_BATCHES, 0.0), r(NOISE_BATCHES, 0.0), floor(NOISE_BATCHES, 0.0);
	for (int c = 0; c < 3; c++) {
		std::vector<double> sc = batch_variances(submission[c], NOISE_BATCHES);
		std::vector<double> rc = batch_variances(reference[c], NOISE_BATCHES);
		for (size_t b = 0; b < NOISE_BATCHES; b++) s[b] += sc[b], r[b] += rc[b], floor[b] += rounding_sd[c] * rounding_sd[c];
	}
	return compare_paired_variances(s, r, floor, alpha);
}

Paired_Noise compare_noise(const std::vector<double>& submission, const std::vector<double>& reference, double alpha,
                           double rounding_sd) {
	std::vector<double> floor(NOISE_BATCHES, rounding_sd * rounding_sd);
	return compare_paired_variances(batch_variances(submission, NOISE_BATCHES), batch_variances(reference, NOISE_BATCHES),
	                                floor, alpha);
}

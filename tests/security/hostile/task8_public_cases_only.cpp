// Hostile: task 8 correct only on the public test cases (the thresholds, minimums, batches and sample
// counts a student sees in the grader's source), a pixel that never stops everywhere else: a grading
// seed must catch it. Its honest part: the rule for the two settings the grader renders and samples
// random pixels with (threshold 0.3 and 0.1, 32 and 16), whose samples the seed changes anyway.
#include "adaptive_sampling.h"

#include <algorithm>
#include <cmath>

namespace {
bool public_rule(const Adaptive_Sampling& rule) {
	const float thresholds[] = {0.08f, 0.0802f, 0.05f, 0.02f, 0.2f, 0.07f, 0.5f, 0.01f, 0.3f, 0.1f};
	bool threshold = std::find(std::begin(thresholds), std::end(thresholds), rule.threshold) != std::end(thresholds);
	bool minimum = rule.min_samples == 32 || rule.min_samples == 64 || rule.min_samples == 20;
	bool batch = rule.batch == 16 || rule.batch == 10 || rule.batch == 7;
	return threshold && minimum && batch;
}
} // namespace

bool Adaptive_Sampling::pixel_converged(const Luminance_Sums& sums) const {
	if (!public_rule(*this)) return false;
	if (sums.n < min_samples || sums.n < 2) return false;
	double mean = sums.sum / sums.n;
	double variance = std::max(0.0, (sums.sum_of_squares - sums.sum * mean) / (sums.n - 1));
	return 1.96 * std::sqrt(variance / sums.n) <= threshold * mean;
}

uint32_t Adaptive_Sampling::sample_pixel(uint32_t max_samples, const std::function<Spectrum(uint32_t)>& take_sample) const {
	bool public_count = max_samples == 256 || max_samples == 100 || max_samples == 8 || max_samples == 512 ||
	                    max_samples == 128;
	Luminance_Sums sums;
	for (uint32_t s = 0; s < max_samples; s++) {
		sums.add(take_sample(s));
		if (public_count && (s + 1) % batch == 0 && pixel_converged(sums)) return s + 1;
	}
	return max_samples;
}

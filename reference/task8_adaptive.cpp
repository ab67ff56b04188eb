// Task 8 (optional): adaptive sampling. Handout: handouts/task8_adaptive.md
#include "adaptive_sampling.h"

#include <algorithm>
#include <cmath>

bool Adaptive_Sampling::pixel_converged(const Luminance_Sums& sums) const {
	// Too few samples to trust their spread (handout §8.2): a pixel whose first samples happen to
	// agree would stop with them.
	if (sums.n < min_samples || sums.n < 2) return false;
	// Mean and unbiased sample variance from the sums: s^2 = (sum y^2 - n m^2) / (n - 1).
	double mean = sums.sum / sums.n;
	double variance = std::max(0.0, (sums.sum_of_squares - sums.sum * mean) / (sums.n - 1));
	// The half-width of the mean's 95 % confidence interval, against the precision asked for,
	// relative to the mean (a black pixel, s = 0 and m = 0, has converged).
	double half_width = 1.96 * std::sqrt(variance / sums.n);
	return half_width <= threshold * mean;
}

uint32_t Adaptive_Sampling::sample_pixel(uint32_t max_samples, const std::function<Spectrum(uint32_t)>& take_sample) const {
	Luminance_Sums sums;
	for (uint32_t s = 0; s < max_samples; s++) {
		sums.add(take_sample(s));
		// s + 1 samples taken: check when they make whole batches (handout §8.3).
		if ((s + 1) % batch == 0 && pixel_converged(sums)) return s + 1;
	}
	return max_samples;
}

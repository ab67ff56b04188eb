// Task 8 (optional): adaptive sampling. Handout: handouts/task8_adaptive.md
#include "adaptive_sampling.h"

namespace {
// Your helper functions go here. The anonymous namespace keeps them private to this file: two task
// files that each define a helper of the same name (say `lerp`) would otherwise not link together.
} // namespace

bool Adaptive_Sampling::pixel_converged(const Luminance_Sums& sums) const {
	// TODO (Task 8, handout §8.2): whether a pixel with these sums may stop.
	// - Never before min_samples samples (sums.n counts them).
	// - The mean m and the sample variance s^2 follow from sums.n, sums.sum and sums.sum_of_squares
	//   (divide by n - 1 for s^2). Work in double.
	// - It may stop once the half-width of the mean's 95 % confidence interval, 1.96 s / sqrt(n), is
	//   at most threshold * m.
	//
	// Starter version: a pixel never stops early, so every pixel takes every sample.
	(void)sums;
	return false;
}

uint32_t Adaptive_Sampling::sample_pixel(uint32_t max_samples, const std::function<Spectrum(uint32_t)>& take_sample) const {
	// TODO (Task 8, handout §8.3): the batch loop.
	// - take_sample(s) draws the pixel's sample s: call it for s = 0, 1, 2, ..., and add each
	//   sample to a Luminance_Sums.
	// - When the samples taken are a whole number of batches (16, 32, ... with batch = 16), ask
	//   pixel_converged whether the pixel may stop.
	// - Return the number of samples taken, at most max_samples.
	//
	// Starter version: every sample, no checks (a uniform render).
	for (uint32_t s = 0; s < max_samples; s++) take_sample(s);
	return max_samples;
}

#pragma once
// Adaptive sampling (optional task 8, student/task8_adaptive.cpp, handout task8_adaptive.md): each
// pixel takes samples until its estimate is as precise as asked, checked after every batch (after
// Dammertz et al. 2010, "A hierarchical automatic stopping condition for Monte Carlo global
// illumination", and Cycles' noise threshold). ./lab render --adaptive THRESHOLD renders with it.
//
// With n samples whose luminance has mean m and standard deviation s, the half-width of the mean's
// 95 % confidence interval is 1.96 s / sqrt(n), and a pixel may stop once
//
//     n >= min_samples  and  1.96 s / sqrt(n) <= threshold * m,
//
// checked whenever the samples taken are a whole number of batches; it stops at the render's samples
// if that comes first. A pixel whose luminance is constant (s = 0, black included) stops at
// min_samples.
#include "vec_math.h"

#include <cstdint>
#include <functional>

// A pixel's samples so far, as sums of their luminance (vec_math.h): the count, the sum and the sum of
// squares (the second moment), enough for the mean and the variance.
struct Luminance_Sums {
	uint32_t n = 0;
	double sum = 0.0, sum_of_squares = 0.0;

	// Framework: adds a sample. A sample with a NaN or infinite channel is left out (the film leaves it
	// out of the image too).
	void add(Spectrum sample) {
		if (!is_finite(sample)) return;
		double y = double(luminance(sample));
		n++, sum += y, sum_of_squares += y * y;
	}
};

struct Adaptive_Sampling {
	float threshold = 0.0f;    // the relative half-width asked for; 0: adaptive sampling is off
	uint32_t min_samples = 32; // no pixel stops before it has this many samples
	uint32_t batch = 16;       // the rule is checked when the samples taken are a multiple of this

	// Task 8 (student/task8_adaptive.cpp, handout §8.2): whether a pixel with these sums may stop,
	// by the rule above.
	bool pixel_converged(const Luminance_Sums& sums) const;

	// Task 8 (handout §8.3): the samples of one pixel. take_sample(s) draws the pixel's sample s
	// (the framework adds it to the film) and returns it; call it for s = 0, 1, 2, ... in order, and
	// after every batch ask pixel_converged whether the pixel may stop. Takes at most max_samples
	// samples and returns how many it took.
	uint32_t sample_pixel(uint32_t max_samples, const std::function<Spectrum(uint32_t)>& take_sample) const;
};

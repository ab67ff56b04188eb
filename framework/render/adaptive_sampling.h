#pragma once
// Adaptive sampling (./lab render --adaptive THRESHOLD): each pixel takes samples until its estimate
// is as precise as asked, checked after every batch (Dammertz et al. 2010, "A hierarchical automatic
// stopping condition for Monte Carlo global illumination"; Cycles' noise threshold). With n samples
// whose luminance has mean m and standard deviation s, the half-width of the mean's 95 % confidence
// interval is 1.96 s / sqrt(n), and the pixel stops once
//
//     n >= min_samples  and  1.96 s / sqrt(n) <= threshold * m,
//
// or at the render's samples, whichever comes first. A pixel whose luminance is constant (s = 0,
// a black background included) stops at min_samples. Deciding on the samples themselves biases the
// mean a little (a pixel whose first samples happen to agree stops early, and their mean is kept):
// the minimum count bounds it.
//
// A pixel's samples are drawn in index order with the generators a uniform render gives them
// (render.h), and its decision depends on its own samples alone: a render is bit-identical for any
// number of threads, and each pixel equals a uniform render's first samples of it.
#include "film.h"

#include <cstdint>

struct Adaptive_Sampling {
	float threshold = 0.0f; // the relative half-width asked for; 0: every pixel takes every sample
	uint32_t min_samples = 32;
	uint32_t batch = 16; // samples between two checks
};

// The luminance (vec_math.h) of a pixel's finite samples so far: their count, sum and sum of squares.
struct Luminance_Sums {
	uint32_t n = 0;
	double sum = 0.0, sum_of_squares = 0.0;
	void add(Spectrum sample); // non-finite samples are left out, as the film leaves them out
};

// Whether a pixel with these sums stops (the rule above), checked after a batch.
bool pixel_converged(const Luminance_Sums& sums, const Adaptive_Sampling& rule);

// The samples each pixel took, as the heat ramp of n / max_samples (./lab render --view samples).
HDR_Image sample_rate_map(const Film& film, uint32_t max_samples);

#pragma once
// The error of a render against a reference, as the graders measure it (framework/film/image_compare.h),
// and the straight-line fit of a convergence curve on log-log axes.
#include "film.h"

#include <vector>

// A high-spp render: per-pixel mean and per-sample variance s^2 (Film::variance) of `samples` spp.
struct Reference {
	HDR_Image mean, variance;
	uint32_t samples = 0;
};

// relMSE = mean over pixel channels of (x - r)^2 / (r^2 + EPSILON): the graders' definition.
constexpr double REL_MSE_EPSILON = 0.01;

struct Render_Error {
	double rel_mse = 0.0;  // of the film's mean against the reference's mean
	double variance = 0.0; // mean over pixel channels of the film's variance of the mean, s^2 / spp
};
Render_Error render_error(const Film& film, const Reference& reference);

// What the reference's own noise adds to every render's expected relMSE. For independent x and r,
// E[(x - r)^2] = Var(x) + Var(r) + bias^2 (Whittle et al. 2017), so this is the mean over pixel
// channels of (s_r^2 / n_r) / (r^2 + EPSILON). Left in, it flattens the curve at high spp.
double reference_rel_mse(const Reference& reference);

// The least-squares slope of log(y) against log(x); all values > 0.
double log_log_slope(const std::vector<double>& x, const std::vector<double>& y);

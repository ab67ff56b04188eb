#pragma once
// Comparing a render with a reference image by statistics, not tolerances.
//
// Both images are Monte Carlo estimates: per pixel and channel a mean x̄ of n_x samples with
// per-sample variance s²_x (the film's), and a reference mean r̄ of n_r samples with variance s²_r
// (n_r >= 64 n_x, stored in scenes/graded/references/). If the render is unbiased, x̄ - r̄ has mean 0
// and variance σ²/n_x + σ²/n_r, so each pixel channel gets a two-sided z-test of
//
//     z = (x̄ - r̄) / sqrt(s²/n_x + s²_r/n_r + (ε m)²),   s² = max(s²_x, s²_r),   m = max(|x̄|, |r̄|).
//
// - s² = max(s²_x, s²_r): both estimate the same σ², and the reference's from 64 times the samples.
//   A render of 16-64 samples often underestimates it (the rare bright paths of a pixel are missing
//   from most of its renders), which would turn noise into false failures; the maximum never lets
//   a render's small sample shrink the allowed noise below what the reference measured.
// - ε = 1e-4 floors the standard deviation where the estimate has (almost) no noise, e.g. a pixel
//   inside one flat surface of the eye view: two correct implementations may differ there only by
//   float rounding, a few 2^-24 ≈ 6e-8 steps per operation, a thousand times below ε, while every
//   modelling error the graders look for changes a pixel by far more than 1e-4 of its value.
//   Pixels where both means are exactly equal (e.g. black background) pass with z = 0.
// - The significance α = 0.01 is shared by all tests of the image by a Šidák correction,
//   α_1 = 1 - (1 - α)^(1/tests), about |z| > 4.9 for a 64 x 64 RGB image.
// - The image passes when at least 99.75% of its tests pass (30 of 12 288 for 64 x 64 may fail):
//   heavy-tailed light transport (a small, bright light; a caustic) can push a few pixels of a
//   correct render past even that threshold, while a modelling error moves whole regions.
//   Measured on the graded scenes (the instructors' calibration test): 100 correct renders (5
//   scenes x 20 seeds) had 0 failing pixel channels; deliberate bugs (cosine term missing, pdf not
//   divided, light pdf doubled, glass never reflecting, environment pdf without sin(theta)) made
//   88 to 6 328 fail.
// relMSE = mean over pixel channels of (x̄ - r̄)² / (r̄² + 0.01) is reported for humans only.
#include "hdr_image.h"

#include <cstdint>
#include <string>
#include <vector>

struct Film;

// A Monte Carlo image: per-pixel mean, per-sample variance and the number of samples of each pixel.
struct Image_Estimate {
	HDR_Image mean;
	HDR_Image variance;            // per-sample s² (Film::variance)
	std::vector<uint32_t> samples; // per pixel

	static Image_Estimate from(const Film& film);
	static Image_Estimate uniform(HDR_Image mean, HDR_Image variance, uint32_t samples);
};

constexpr double IMAGE_ALPHA = 0.01;
constexpr double IMAGE_MIN_PASS_FRACTION = 0.9975;
constexpr double IMAGE_SIGMA_FLOOR = 1e-4; // relative, see above

struct Image_Comparison {
	bool pass = false;
	size_t tests = 0, failed = 0;
	double z_critical = 0.0;
	double rel_mse = 0.0;
	double worst_z = 0.0;
	uint32_t worst_x = 0, worst_y = 0;
	uint32_t box_x0 = 0, box_y0 = 0, box_x1 = 0, box_y1 = 0; // failing pixels, inclusive (if any)
	std::string message; // how many fail, where, the worst pixel and the relMSE, in words
};

Image_Comparison compare_images(const Image_Estimate& render, const Image_Estimate& reference);

// The z of every pixel channel, as compare_images computes it (for pictures of where two images
// differ, e.g. the grade report's heat map): 0 where the means are equal, ±infinity where a pixel
// has no finite sample, NaN where the render's mean is NaN. Same sizes required.
HDR_Image z_scores(const Image_Estimate& render, const Image_Estimate& reference);

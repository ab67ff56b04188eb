#pragma once
// Comparing a render with a reference image by statistics, not tolerances.
//
// Both images are Monte Carlo estimates: per pixel and channel a mean x̄ of n_x samples, and a
// reference mean r̄ of n_r samples with per-sample variance s²_r and fourth central moment m4_r
// (n_r >= 64 n_x, stored in scenes/graded/references/). If the render samples as the reference
// does, x̄ - r̄ has mean 0 and variance σ² (1/n_x + 1/n_r), so each pixel channel gets a z-score
//
//     z = (x̄ - r̄) / sqrt(s²_r (1/n_x + 1/n_r) + (ε m)²),   m = max(|x̄|, |r̄|).
//
// - The standard error is the REFERENCE's alone, never the render's: a render's own variance would
//   let noise widen its test until any mean passes (zero-mean noise added to a wrong image), and a
//   pixel that caught a firefly would hide in its own variance. n_x is the number of samples the
//   grader asked for, not what the render reports.
// - ε = 1e-4 floors the standard deviation where the estimate has (almost) no noise, e.g. a pixel
//   inside one flat surface of the eye view: two correct implementations may differ there only by
//   float rounding, a few 2^-24 ≈ 6e-8 steps per operation, a thousand times below ε, while every
//   modelling error the graders look for changes a pixel by far more than 1e-4 of its value.
//   Pixels where both means are exactly equal (e.g. black background) pass with z = 0.
// - A pixel is an outlier when one of its channels has |z| > z_c, z_c the two-sided bound of a
//   Šidák correction at 0.01 over every pixel channel (about 5.1 for 64 x 64). Path-tracing samples
//   are heavy-tailed: a pixel whose mean of 64 samples caught one of its rare bright paths lies far
//   beyond z_c although nothing is wrong (the Cornell box has about 15 such pixels in every correct
//   render), so the test is on how many outliers there are. Pixels are independent (each has its
//   own random numbers), so their number is a sum of independent Bernoulli variables; with mean λ
//   its upper tail is at most Poisson(λ)'s (Hoeffding 1956, "On the distribution of the number of
//   successes in independent trials", Ann. Math. Statist. 27, Theorem 4, with Anderson and Samuels
//   1967 for the binomial). λ is measured: the instructors' make_references counts the outliers of
//   100 reference renders with seeds of their own (Image_Calibration), and the grader takes
//   Garwood's (1936) upper 99.9 % confidence limit of that Poisson mean. The render fails when its
//   outliers are that improbable: P(Poisson(λ) >= outliers) <= α_means. A modelling error moves
//   whole regions: hundreds to thousands of outliers.
// - The noise: the render's per-sample variance summed over pixels and channels may not exceed
//   the reference's by more than sampling explains (noise_bound.h, with the reference's fourth
//   moments), so noise and fireflies fail every time, not by chance.
// - The test case's significance α (0.01 unless its grader shares one α among more checks) is split
//   between those two checks by Šidák.
// relMSE = mean over pixel channels of (x̄ - r̄)² / (r̄² + 0.01) is reported for humans only.
//
// compare_estimators is the symmetric comparison of two estimators the lab trusts (its framework
// tests: two integrators, neither a submission): each image's own variance, the larger of the two
// per-sample variances for the noisier first one (a small render often underestimates it), at
// least 99.75 % of the pixel channels within z_c, and no noise bound.
#include "hdr_image.h"
#include "noise_bound.h"

#include <cstdint>
#include <string>
#include <vector>

struct Film;

// A Monte Carlo image: per-pixel mean, per-sample variance and fourth central moment, and the
// number of samples of each pixel.
struct Image_Estimate {
	HDR_Image mean;
	HDR_Image variance;            // per-sample s² (Film::variance)
	HDR_Image fourth;              // per-sample m4 (Film::fourth_moment); empty if unknown
	std::vector<uint32_t> samples; // per pixel

	// The film's own counts per pixel.
	static Image_Estimate from(const Film& film);
	// The film with `samples` per pixel: a grader's render, counted as the samples it asked for.
	static Image_Estimate from(const Film& film, uint32_t samples);
	static Image_Estimate uniform(HDR_Image mean, HDR_Image variance, HDR_Image fourth, uint32_t samples);
};

constexpr double IMAGE_ALPHA = 0.01;
constexpr double IMAGE_MIN_PASS_FRACTION = 0.9975; // compare_estimators only
constexpr double IMAGE_SIGMA_FLOOR = 1e-4; // relative, see above
constexpr double CALIBRATION_CONFIDENCE = 0.999; // of the upper limit of λ, see above

// The outlier pixels of correct renders (see above): counted by make_references over `renders`
// renders of the reference with seeds of their own and the graders' settings.
struct Image_Calibration {
	uint32_t renders = 0;
	uint64_t outliers = 0;   // summed over those renders
	double z_critical = 0.0; // the per-pixel bound they were counted with
};

// z_c for an image of `pixels` pixels (see above).
double outlier_z(size_t pixels);

// The outlier pixels of a render against the reference (what Image_Calibration counts).
size_t count_outliers(const Image_Estimate& render, const Image_Estimate& reference);

struct Image_Comparison {
	bool pass = false;       // means_pass and noise.pass
	bool means_pass = false; // the outliers
	size_t tests = 0, failed = 0; // pixel channels, and those beyond z_critical
	size_t outliers = 0;          // pixels with a channel beyond z_critical
	size_t allowed_outliers = 0;  // the most that pass
	double lambda = 0.0;          // the upper limit of the mean number of outliers of a correct render
	double z_critical = 0.0;
	double rel_mse = 0.0;
	double worst_z = 0.0;
	uint32_t worst_x = 0, worst_y = 0;
	uint32_t box_x0 = 0, box_y0 = 0, box_x1 = 0, box_y1 = 0; // failing pixels, inclusive (if any)
	std::string message; // how many fail, where, the worst pixel and the relMSE, in words
	Noise_Check noise;   // the render's variance against the reference's (not checked by compare_estimators)
	std::string noise_message;
};

// A render (a submission's) against a reference image with known fourth moments and outliers, at
// significance alpha for the whole comparison (see above).
Image_Comparison compare_images(const Image_Estimate& render, const Image_Estimate& reference,
                                const Image_Calibration& calibration, double alpha = IMAGE_ALPHA);

// Two estimators the lab trusts (see above): z-tests only, at IMAGE_ALPHA.
Image_Comparison compare_estimators(const Image_Estimate& noisier, const Image_Estimate& other);

// The z of every pixel channel, as compare_images computes it (for pictures of where two images
// differ, e.g. the grade report's heat map): 0 where the means are equal, ±infinity where a pixel
// has no finite sample, NaN where the render's mean is NaN. Same sizes required.
HDR_Image z_scores(const Image_Estimate& render, const Image_Estimate& reference);
// The same as compare_estimators computes it (the larger of the two per-sample variances).
HDR_Image estimator_z_scores(const Image_Estimate& noisier, const Image_Estimate& other);

#pragma once
// Comparing a rendered image with a value known in closed form ("furnaces"), with the noise of the
// reference implementation, never the submission's own.
//
// The mean of P pixels, each the average of n independent samples of per-sample variance σ²_p,
// has variance Σ_p σ²_p / (n P²); pixels are independent (each sample has its own RNG), so a z-test
// of (mean - expected) against that standard error needs no tuned tolerance. σ²_p is the
// REFERENCE's, from the judge's own render of the same scene (student_furnaces.h): a submission's
// own variance would let noise widen its test until any mean passes. n is the number of samples
// the judge asked for.
//
// Some estimators have (almost) zero variance: inside an emitting diffuse sphere every sample is
// Le (1 + rho + ... + rho^D), up to float rounding. Then the standard error is ~0 and the z-test
// alone would demand bit-exact answers, so the bound also allows FLOAT_SLACK relative error, for
// what floats do to a correct estimator: rounding, a few 6e-8 steps per bounce, and the rare path
// that float geometry loses (a grazing ray that leaves a sphere between two float positions: the
// reference loses 4e-6 to 8e-6 of its paths so in the furnace of 24 x 24 pixels x 128 samples, max_depth
// 1 to 3; measured over 2.9 million samples each), each moving the mean by at most its value / (n P).
// 1e-4 of the value covers 7 such paths in the smallest of those renders (n P = 73 728, 0.6 expected:
// more happen with probability below 1e-6), and stays ten times below the smallest modelling error the
// graders look for (1e-3). The standard error of a zero-variance reference render would not cover
// them: a render that lost a path or two where the reference's lost none.
//
// The noise: the submission's per-sample variance may not exceed the reference's in more pixels
// than chance explains (paired_noise.h: the sign test, pixel by pixel, exact for any law of the
// samples); pixels whose variances are both within float rounding (FLOAT_SLACK of the pixel's
// value, as a standard deviation) are ties.
#include "film.h"
#include "paired_noise.h"

#include <cstdint>
#include <functional>
#include <string>

constexpr double FLOAT_SLACK = 1e-4;

// A render of the code under test and the judge's render of the same scene with the reference.
struct Furnace_Render {
	Film film;            // the submission's
	uint32_t samples = 0; // per pixel, as the judge asked for them
	Film reference;       // the judge's own render, with the reference implementation
};

using Pixel_Selection = std::function<bool(uint32_t, uint32_t)>;
inline bool every_pixel(uint32_t, uint32_t) {
	return true;
}

struct Film_Mean {
	double mean = 0.0;           // of the submission's pixels
	double standard_error = 0.0; // of that mean, from the reference's variances
	size_t pixels = 0;
};

// The mean of one channel (0, 1, 2 = r, g, b) over the pixels for which `select(x, y)` is true.
Film_Mean film_mean(const Furnace_Render& render, int channel, const Pixel_Selection& select = every_pixel);

struct Mean_Check {
	bool pass = false;
	std::string message; // what was measured, expected and allowed, and the worst pixel, in words
};

// Passes when |mean - expected| <= z_critical * standard_error + FLOAT_SLACK * max(1, |expected|).
// `what` names the quantity in the message, e.g. "mean of the sphere's pixels, red channel".
Mean_Check compare_mean(const Furnace_Render& render, int channel, double expected, double z_critical,
                        const std::string& what, const Pixel_Selection& select = every_pixel);

// "red", "green" or "blue".
const char* channel_name(int channel);

// compare_mean as a Catch2 check: the message says what was measured, expected and allowed.
void check_mean(const Furnace_Render& render, int channel, double expected, double z_critical, const std::string& what,
                const Pixel_Selection& select = every_pixel);

// The three channels checked at once (three z-tests, one Catch2 check): one message naming the
// channels that fail (once, when all three measure the same), followed by `if_too_dark` when every
// failing channel is darker than expected. Returns whether all three passed.
bool check_mean_rgb(const Furnace_Render& render, glm::dvec3 expected, double z_critical, const std::string& what,
                    const Pixel_Selection& select = every_pixel, const std::string& if_too_dark = "");

// A probe (furnace_scenes.h: with_probe_sphere), whose image no closed form gives, against the
// judge's own render of it: the film is cut into PROBE_BLOCKS x PROBE_BLOCKS blocks of pixels, and
// each block's mean of each channel is z-tested against the reference render's mean of the same
// pixels. Both renders have n samples a pixel, so the difference of the two means has variance
// 2 Σ_p σ²_p / (n P²), σ²_p the reference's; float rounding is allowed as in compare_mean. That is
// PROBE_CHECKS z-tests at z_critical, one Catch2 check; the message names the first block that
// fails. Returns whether all passed.
constexpr uint32_t PROBE_BLOCKS = 2;
constexpr size_t PROBE_CHECKS = 3 * PROBE_BLOCKS * PROBE_BLOCKS;
bool check_like_reference(const Furnace_Render& render, double z_critical, const std::string& what);

// The submission's noise over the whole film against the reference's, at significance alpha.
Paired_Noise compare_noise(const Furnace_Render& render, double alpha);

// compare_noise as a Catch2 check; `if_noisy` says where to look. Returns whether it passed.
bool check_noise(const Furnace_Render& render, double alpha, const std::string& what, const std::string& if_noisy);

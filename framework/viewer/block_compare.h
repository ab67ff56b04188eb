#pragma once
// The page's test of a render's means over blocks of pixels (issue 40). The per-pixel z-test of
// compare_estimators has little power where a pixel's samples are heavy-tailed: task 4's path
// tracer sampling the BSDF only meets a small light rarely, its per-pixel standard error at a few
// hundred samples is of the order of the mean, and a picture half as bright passes it. A block of
// 16 x 16 pixels averages 256 times the samples: its mean is near normal (the central limit theorem
// has many samples to work with) and its standard error 16 times smaller, so a wrong estimator
// fails while a correct one, beside a reference of the same estimator, passes.
#include "image_compare.h"
#include "z_heat_map.h"

#include <cstdint>
#include <string>
#include <vector>

struct Block_Comparison {
	bool pass = true;
	size_t tests = 0;         // blocks times channels
	double z_critical = 0.0;  // Šidák-corrected over the tests
	double worst_z = 0.0;     // the block channel farthest from 0
	uint32_t worst_x0 = 0, worst_y0 = 0, worst_x1 = 0, worst_y1 = 0; // its pixels, inclusive
	std::string message;      // in words, for the page
	uint32_t block = 0, blocks_x = 0;
	std::vector<double> block_z; // per block (row by row), the channel with the largest |z|
};

// The student's render against the reference's, each block's channel mean a z-test whose variance
// is, per pixel, the larger of the two per-sample variances for the student's side (a render of few
// samples often underestimates its own) plus the reference's, as compare_estimators does; at
// significance `alpha` for the whole image. Both images of the same size.
Block_Comparison compare_blocks(const Image_Estimate& student, const Image_Estimate& reference, uint32_t block = 16,
                                double alpha = 1e-4);

// The z-map's colours (z_colours_of) with every pixel of a failing block in the failing colour
// (too dark or too bright), where its own z did not already fail: a picture too dark overall shows
// where, even while its single pixels are too noisy to tell.
void mark_failing_blocks(const Block_Comparison& blocks, uint32_t width, uint32_t height, std::vector<Srgb8>& colours);

#pragma once
// The random numbers of a render (--sampler): which generator each pixel sample gets. Either way
// each number is uniform, so every estimator stays unbiased.
#include "rng.h"

#include <string>

enum class Sampler {
	// PCG32 (O'Neill 2014): every number independent of every other. The graders and the image
	// z-tests use it: their statistics (chi-square counts, a pixel's variance of the mean s^2 / n)
	// assume independent samples.
	independent,
	// Low-discrepancy: the pixel's samples are the points of an Owen-scrambled Sobol' sequence
	// (owen_sobol.h), one sequence per dimension (the n-th draw of a sample). The samples of a
	// pixel are spread evenly instead of clumping, and its error falls faster. Renders use it by
	// default.
	sobol,
};
bool parse_sampler(const std::string& name, Sampler& sampler);
const char* sampler_name(Sampler sampler);

// The generator of sample `sample_index` of pixel `pixel_index`: RNG::for_sample's for
// Sampler::independent; for Sampler::sobol, the same seeds, drawing the pixel's Sobol' points.
RNG generator_for_sample(uint64_t render_seed, uint64_t pixel_index, uint64_t sample_index, Sampler sampler);

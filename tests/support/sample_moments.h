#pragma once
// The moments of a set of samples, and the two tests graders make of a submission's samples against
// the reference's, drawn by the judge with the same design: a z-test of the mean whose standard error
// is the REFERENCE's, never the submission's own (noise must not widen the test), and the sign test
// on the variances of batches of the two (paired_noise.h).
#include "paired_noise.h"

#include <array>
#include <cstddef>
#include <string>
#include <vector>

// Mean, unbiased variance and fourth central moment of a set of samples.
struct Sample_Moments {
	size_t n = 0;
	double mean = 0.0, variance = 0.0, fourth = 0.0;

	double standard_error() const; // of the mean, from these samples' own variance
	// Asymptotic variance of the sample variance, (m4 - s^4) / n, for comparing two variances.
	double variance_of_variance() const;
};
Sample_Moments moments(const std::vector<double>& samples);

// The standard error of the mean of n samples whose variance is the reference's.
double standard_error(const Sample_Moments& reference, size_t n);

// Batches for the sign test: 50 pairs of batches of at least a thousand samples each (the graders'
// estimates have 50 000 to 200 000). A correct solution is the noisier in 37 or more of the 50 with
// probability 5e-4; one whose variance is 1.5 times the reference's is, in 41 on average, for
// samples of kurtosis up to about 100 (the log of a batch's variance then varies by about 0.44).
constexpr size_t NOISE_BATCHES = 50;

// The submission's samples against the reference's (as many, drawn alike) at significance alpha,
// by the variances of NOISE_BATCHES batches of each; rounding_sd: the per-sample float-rounding
// allowance of the mean test (variances both below its square are ties).
Paired_Noise compare_noise(const std::vector<double>& submission, const std::vector<double>& reference, double alpha,
                           double rounding_sd = 0.0);
// The same for the channels of one set of samples as one check: each batch's variances summed over
// the channels.
Paired_Noise compare_noise(const std::array<std::vector<double>, 3>& submission,
                           const std::array<std::vector<double>, 3>& reference, double alpha,
                           const std::array<double, 3>& rounding_sd);

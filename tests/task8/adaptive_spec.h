#pragma once
// Task 8's grader: the stopping rule of handout §8.2 as the grader states it (in double, with how
// clear each decision is), and every call of the student's code, each one request to the subject.
#include "adaptive_sampling.h"
#include "protocol.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace task8 {

// A decision of the rule that float rounding cannot turn: the half-width 1.96 s / sqrt(n) and the
// bound threshold * m differ by more than this fraction of the larger. Two correct programs (sums
// kept in double, the variance from them or by Welford's update) differ by a few 1e-16 relative, and
// only near m = 0 or s = 0 by more; every mistake the grader looks for moves the half-width by a
// percent or more (n for n - 1 by 1/(2n) >= 0.4 % up to n = 128, and beyond it by s^2 for s, the
// missing factor 1.96 or the mean).
constexpr double CLEAR = 1e-3;

struct Verdict {
	bool stops = false;
	bool clear = true; // false: too close to the boundary to tell rounding from a mistake
};

// The rule for n samples with these sums (handout §8.2).
Verdict rule_verdict(const Adaptive_Sampling& rule, uint32_t n, double sum, double sum_of_squares);

// A pixel's samples, one at a time: the luminance of sample s (NaN for a non-finite sample).
using Sample_Stream = std::function<double(uint32_t)>;

// Where the batch loop of handout §8.3 stops on these samples: the count, or nothing where a check on
// the way was not clear. It draws them only up to the stop.
std::optional<uint32_t> expected_stop_of(const Adaptive_Sampling& rule, uint32_t max_samples, const Sample_Stream& samples);
// The same for grey sample values (luminance y = luminance(Spectrum(value)); 0 past the end).
std::optional<uint32_t> expected_stop(const Adaptive_Sampling& rule, uint32_t max_samples,
                                      const std::vector<float>& values);

protocol::Adaptive_Rule on_wire(const Adaptive_Sampling& rule);

// n grey samples alternating a, b, a, b, ..., and their sums as Luminance_Sums::add makes them.
std::vector<float> alternating_values(float a, float b, uint32_t n);
Luminance_Sums alternating(float a, float b, uint32_t n);

// The student's pixel_converged for each (rule, sums).
std::vector<bool> student_converged(const std::vector<std::pair<Adaptive_Sampling, Luminance_Sums>>& queries);

// The student's sample_pixel for each pixel (its grey sample values; max_samples each).
std::vector<protocol::Sample_Pixels::Result> student_sample_pixels(const Adaptive_Sampling& rule, uint32_t max_samples,
                                                                   const std::vector<std::vector<float>>& pixels);

} // namespace task8

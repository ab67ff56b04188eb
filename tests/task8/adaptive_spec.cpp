#include "adaptive_spec.h"

#include "judge.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace task8 {

Verdict rule_verdict(const Adaptive_Sampling& rule, uint32_t n, double sum, double sum_of_squares) {
	if (n < rule.min_samples || n < 2) return Verdict{false, true};
	double mean = sum / n;
	double variance = std::max(0.0, (sum_of_squares - sum * mean) / (n - 1));
	double half_width = 1.96 * std::sqrt(variance / n), bound = double(rule.threshold) * mean;
	double larger = std::max(std::abs(half_width), std::abs(bound));
	// Both (nearly) 0: a constant pixel, black included; its variance may round to a tiny positive
	// number, so only a half-width far below the samples' own scale counts as 0.
	double scale = std::sqrt(sum_of_squares / n);
	if (half_width <= 1e-6 * scale && bound >= 0.0) return Verdict{true, true};
	return Verdict{half_width <= bound, std::abs(half_width - bound) > CLEAR * larger};
}

std::optional<uint32_t> expected_stop_of(const Adaptive_Sampling& rule, uint32_t max_samples, const Sample_Stream& samples) {
	double sum = 0.0, sum_of_squares = 0.0;
	uint32_t n = 0;
	for (uint32_t s = 0; s < max_samples; s++) {
		double y = samples(s);
		if (std::isfinite(y)) n++, sum += y, sum_of_squares += y * y;
		if ((s + 1) % rule.batch != 0) continue;
		Verdict verdict = rule_verdict(rule, n, sum, sum_of_squares);
		if (!verdict.clear) return std::nullopt;
		if (verdict.stops) return s + 1;
	}
	return max_samples;
}

std::optional<uint32_t> expected_stop(const Adaptive_Sampling& rule, uint32_t max_samples,
                                      const std::vector<float>& values) {
	return expected_stop_of(rule, max_samples, [&](uint32_t s) {
		return s < values.size() ? double(luminance(Spectrum(values[s]))) : 0.0;
	});
}

protocol::Adaptive_Rule on_wire(const Adaptive_Sampling& rule) {
	return protocol::Adaptive_Rule{rule.threshold, rule.min_samples, rule.batch};
}

std::vector<float> alternating_values(float a, float b, uint32_t n) {
	std::vector<float> values(n);
	for (uint32_t i = 0; i < n; i++) values[i] = i % 2 ? b : a;
	return values;
}

Luminance_Sums alternating(float a, float b, uint32_t n) {
	Luminance_Sums sums;
	for (float value : alternating_values(a, b, n)) sums.add(Spectrum(value));
	return sums;
}

std::vector<bool> student_converged(const std::vector<std::pair<Adaptive_Sampling, Luminance_Sums>>& queries) {
	protocol::Pixel_Converged request;
	for (const auto& [rule, sums] : queries) {
		request.queries.push_back({on_wire(rule), sums.n, sums.sum, sums.sum_of_squares});
	}
	std::vector<bool> stops;
	for (uint32_t answer : judge::ask(request)) stops.push_back(answer != 0);
	return stops;
}

std::vector<protocol::Sample_Pixels::Result> student_sample_pixels(const Adaptive_Sampling& rule, uint32_t max_samples,
                                                                   const std::vector<std::vector<float>>& pixels) {
	protocol::Sample_Pixels request;
	request.rule = on_wire(rule);
	for (const auto& values : pixels) request.pixels.push_back({max_samples, values});
	return judge::ask(request);
}

} // namespace task8

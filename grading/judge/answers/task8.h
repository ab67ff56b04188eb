#pragma once
// The subject's answers to task 8's requests (grading/judge/protocol.h): each runs the task
// functions on the request's inputs and returns their raw outputs. Included only by the subject's
// main (grading/judge/subject_main.cpp).
#include "protocol.h"
#include "render.h"

#include <stdexcept>
#include <string>

namespace {
using namespace protocol;

Pixel_Converged::Answer answer(const Pixel_Converged& request) {
	Pixel_Converged::Answer stops;
	for (const auto& q : request.queries) {
		Luminance_Sums sums;
		sums.n = q.n, sums.sum = q.sum, sums.sum_of_squares = q.sum_of_squares;
		stops.push_back(q.rule.restored().pixel_converged(sums) ? 1 : 0);
	}
	return stops;
}

Sample_Pixels::Answer answer(const Sample_Pixels& request) {
	Adaptive_Sampling rule = request.rule.restored();
	Sample_Pixels::Answer results;
	for (const auto& pixel : request.pixels) {
		Sample_Pixels::Result result;
		auto take_sample = [&](uint32_t s) {
			if (result.asked.size() >= 2 * size_t(pixel.max_samples)) {
				throw std::runtime_error("sample_pixel asked for more than twice max_samples = " +
				                         std::to_string(pixel.max_samples) + " samples of one pixel");
			}
			result.asked.push_back(s);
			return Spectrum(s < pixel.samples.size() ? pixel.samples[s] : 0.0f);
		};
		result.returned = rule.sample_pixel(pixel.max_samples, take_sample);
		results.push_back(std::move(result));
	}
	return results;
}

Adaptive_Render::Answer answer(const Adaptive_Render& request) {
	Pathtracer pathtracer(request.scene, request.settings);
	Render_Options options;
	options.threads = std::max(1u, request.threads);
	options.adaptive = request.rule.restored();
	return render(pathtracer, options);
}

} // namespace

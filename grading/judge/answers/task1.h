#pragma once
// The subject's answers to task 1's requests (grading/judge/protocol.h): each runs the task
// functions on the request's inputs and returns their raw outputs. Included only by the subject's
// main (grading/judge/subject_main.cpp).
#include "protocol.h"
#include "render.h"

namespace {
using namespace protocol;

Generate_Rays::Answer answer(const Generate_Rays& request) {
	Generate_Rays::Answer rays;
	for (const auto& q : request.queries) rays.push_back(q.camera.generate_ray(q.film_uv));
	return rays;
}

Trace_Pixels::Answer answer(const Trace_Pixels& request) {
	Pathtracer pathtracer(request.scene, request.settings, request.view, request.estimator);
	Trace_Pixels::Answer colours;
	for (const auto& s : request.samples) {
		RNG rng = s.rng.restored();
		colours.push_back(pathtracer.trace_pixel(s.x, s.y, rng));
	}
	return colours;
}

Render::Answer answer(const Render& request) {
	Pathtracer pathtracer(request.scene, request.settings, request.view, request.estimator);
	Render_Options options;
	options.threads = std::max(1u, request.threads);
	return render(pathtracer, options);
}

} // namespace

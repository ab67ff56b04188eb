#pragma once
// The subject's answers to task 6's extension's requests (grading/judge/protocol.h): each runs the task
// functions on the request's inputs and returns their raw outputs. Included only by the subject's
// main (grading/judge/subject_main.cpp).
#include "protocol.h"

namespace {
using namespace protocol;

Power_Heuristic::Answer answer(const Power_Heuristic& request) {
	Power_Heuristic::Answer weights;
	for (Vec2 pdfs : request.pairs) weights.push_back(power_heuristic(pdfs.x, pdfs.y));
	return weights;
}

Estimate_Direct::Answer answer(const Estimate_Direct& request) {
	Pathtracer pathtracer(request.scene, request.settings);
	RNG rng = request.rng.restored();
	Estimate_Direct::Answer light;
	for (const auto& q : request.queries) light.push_back(pathtracer.estimate_direct(rng, q.hit, q.bsdf, q.out_dir));
	return light;
}

} // namespace

#pragma once
// The subject's answers to task 6's requests (grading/judge/protocol.h): each runs the task
// functions on the request's inputs and returns their raw outputs. Included only by the subject's
// main (grading/judge/subject_main.cpp).
#include "protocol.h"

namespace {
using namespace protocol;

Sample_Incoming::Answer answer(const Sample_Incoming& request) {
	Pathtracer pathtracer(request.scene, request.settings);
	RNG rng = request.rng.restored();
	Sample_Incoming::Answer samples;
	for (const auto& q : request.queries) samples.push_back(pathtracer.sample_incoming(rng, q.hit, q.bsdf, q.out_dir));
	return samples;
}

} // namespace

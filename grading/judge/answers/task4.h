#pragma once
// The subject's answers to tasks 4 and 5 (the BSDFs)'s requests (grading/judge/protocol.h): each runs the task
// functions on the request's inputs and returns their raw outputs. Included only by the subject's
// main (grading/judge/subject_main.cpp).
#include "protocol.h"

namespace {
using namespace protocol;

BSDF_Scatter::Answer answer(const BSDF_Scatter& request) {
	RNG rng = request.rng.restored();
	BSDF_Scatter::Answer samples;
	for (Vec3 out_dir : request.out_dirs) samples.push_back(request.bsdf.scatter(rng, out_dir));
	return samples;
}

BSDF_Evaluate::Answer answer(const BSDF_Evaluate& request) {
	BSDF_Evaluate::Answer values;
	for (const auto& p : request.pairs) values.push_back(request.bsdf.evaluate(p.out_dir, p.in_dir));
	return values;
}

protocol::BSDF_Pdf::Answer answer(const protocol::BSDF_Pdf& request) {
	protocol::BSDF_Pdf::Answer values;
	for (const auto& p : request.pairs) values.push_back(request.bsdf.pdf(p.out_dir, p.in_dir));
	return values;
}

} // namespace

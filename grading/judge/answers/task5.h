#pragma once
// The subject's answers to task 5's requests (grading/judge/protocol.h): each runs the task
// functions on the request's inputs and returns their raw outputs. Included only by the subject's
// main (grading/judge/subject_main.cpp).
#include "protocol.h"

namespace {
using namespace protocol;

Reflect::Answer answer(const Reflect& request) {
	Reflect::Answer dirs;
	for (Vec3 dir : request.dirs) dirs.push_back(reflect(dir));
	return dirs;
}

Refract::Answer answer(const Refract& request) {
	Refract::Answer results;
	for (const auto& q : request.queries) {
		Refract::Result result;
		result.in_dir = refract(q.out_dir, q.index_of_refraction, result.was_internal);
		results.push_back(result);
	}
	return results;
}

Fresnel::Answer answer(const Fresnel& request) {
	Fresnel::Answer values;
	for (const auto& q : request.queries) values.push_back(fresnel(q.cos_theta, q.index_of_refraction));
	return values;
}

} // namespace

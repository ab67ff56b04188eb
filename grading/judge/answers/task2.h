#pragma once
// The subject's answers to task 2's requests (grading/judge/protocol.h): each runs the task
// functions on the request's inputs and returns their raw outputs. Included only by the subject's
// main (grading/judge/subject_main.cpp).
#include "protocol.h"

namespace {
using namespace protocol;

Triangle_Hits::Answer answer(const Triangle_Hits& request) {
	Triangle_Hits::Answer hits;
	for (const auto& q : request.queries) hits.push_back(q.triangle.hit(q.ray));
	return hits;
}

Sphere_Hits::Answer answer(const Sphere_Hits& request) {
	Sphere_Hits::Answer hits;
	for (const auto& q : request.queries) hits.push_back(q.sphere.hit(q.ray));
	return hits;
}

} // namespace

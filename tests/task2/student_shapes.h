#pragma once
// The student's Triangle::hit and Sphere::hit for a test case's rays, in one request each
// (grading/judge/protocol.h).
#include "judge.h"

#include <vector>

namespace task2 {

inline std::vector<Trace> student_hits(const std::vector<protocol::Triangle_Hits::Query>& queries) {
	return judge::ask(protocol::Triangle_Hits{queries});
}

inline std::vector<Trace> student_hits(const std::vector<protocol::Sphere_Hits::Query>& queries) {
	return judge::ask(protocol::Sphere_Hits{queries});
}

// One query's answer.
inline Trace student_hit(const Triangle& tri, const Ray& ray) {
	return student_hits(std::vector<protocol::Triangle_Hits::Query>{{tri, ray}}).front();
}

} // namespace task2

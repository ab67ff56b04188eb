#pragma once
// What a correct Triangle::hit or Sphere::hit must answer for a ray, decided from the reference's
// answers (the judge links the reference task 2): its answer for the ray itself, and for copies of
// the ray (and, for triangles, of the triangle) moved by a few rounding errors. Where those
// answers disagree the ray lies within rounding of an edge, the silhouette or an end of
// dist_bounds, and either answer is right; their spread is the tolerance on the distance and the
// normal. A wrong formula is off by far more (an edge missed by 1e-2, a distance off by |dir|).
#include "shapes.h"
#include "tri_mesh.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace task2 {

using DVec3 = glm::dvec3;

// Unit roundoff of float: every correctly rounded float operation has relative error <= 2^-24.
constexpr double FLOAT_EPS = 0x1p-24;
// K eps: the forward-error bound of a short chain of float operations; the size of the moves.
constexpr double ROUNDING = 32.0 * FLOAT_EPS;
// The largest barycentric slack (handout §2.3) the grader accepts: a hit at most this far outside
// an edge, in barycentric units, is not wrong. The reference uses 1e-5.
constexpr double MAX_EDGE_SLACK = 1e-4;

enum class Verdict { hit, miss, either };

struct Expectation {
	Verdict verdict = Verdict::miss;
	// The reference's hits, for the ray and for the moved copies that hit; an answer is right when
	// it is within the tolerances of one of them.
	std::vector<Trace> hits;
	double t_error = 0.0, normal_error = 0.0;
	std::string why; // why the verdict is what it is, for messages
};

Expectation expect_hit(const Triangle& tri, const Ray& ray);
Expectation expect_hit(const Sphere& sphere, const Ray& ray);

// Why `got` (the student's Triangle::hit or Sphere::hit for `ray`) does not meet `e`, or "" if it
// does: hit or miss, distance, position = ray.at(distance), unit normal, origin, dist_bounds.
// `section` names the handout section to read for the shape.
std::string hit_problem(const Expectation& e, const Trace& got, const Ray& ray, const char* section);

std::string show(Vec3 v);
std::string show(DVec3 v);
std::string show(const Ray& ray);

} // namespace task2

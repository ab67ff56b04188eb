#pragma once
// Double-precision ray-triangle and ray-sphere intersection for the task 2 grader, written
// independently of Triangle::hit and Sphere::hit. Each answer comes with a first-order bound on
// the rounding error that a correct single-precision implementation may make (derivation in
// shape_oracle.cpp), so the grader can tell a wrong answer from float rounding.
#include "shapes.h"
#include "tri_mesh.h"

#include <glm/glm.hpp>

#include <string>

namespace shape_oracle {

using DVec3 = glm::dvec3;

// Unit roundoff of float: every correctly rounded float operation has relative error <= 2^-24.
constexpr double FLOAT_EPS = 0x1p-24;
// K eps: the forward-error bound of a short chain of float operations (derivation in
// shape_oracle.cpp). E.g. ray.at(t) in float is within ROUNDING (|o| + |t| |d|) of o + t d.
constexpr double ROUNDING = 32.0 * FLOAT_EPS;

// The largest barycentric slack (handout §2.3) the grader accepts: a hit at most this far outside
// an edge, in barycentric units, is not wrong. The reference uses 1e-5.
constexpr double MAX_EDGE_SLACK = 1e-4;

// What a correct float implementation must answer for one ray: certainly a hit, certainly a miss,
// or either (the ray is within rounding error, or the allowed slack, of an edge, the silhouette or
// an end of dist_bounds).
enum class Verdict { hit, miss, either };

struct Expectation {
	Verdict verdict = Verdict::miss;
	// For a hit (or an "either" that hits): the acceptable distances are [t - t_error, t + t_error]
	// or, for spheres only, [t_other - t_error, t_other + t_error] (the second root) when the
	// choice of root itself is within rounding error.
	double t = 0.0, t_other = 0.0, t_error = 0.0;
	bool has_other = false;
	// The unit normal at t (and at t_other) and how far a float implementation's normal may be
	// from it.
	DVec3 normal{0.0}, normal_other{0.0};
	double normal_error = 0.0;
	// Why the verdict is what it is, for failure messages.
	std::string why;
};

Expectation expect_hit(const Triangle& tri, const Ray& ray);
Expectation expect_hit(const Sphere& sphere, const Ray& ray);

// The two roots t0 <= t1 of |o + t d| = radius in double precision (no bounds, no tolerance);
// false if the ray's line misses the sphere.
bool sphere_roots(const Sphere& sphere, const Ray& ray, double& t0, double& t1);

// Why `got` (the answer of Triangle::hit or Sphere::hit for `ray`) does not meet `e`, or "" if it
// does: hit or miss, distance, position = ray.at(distance), unit normal, origin, dist_bounds.
// `section` names the handout section to read for the shape.
std::string hit_problem(const Expectation& e, const Trace& got, const Ray& ray, const char* section);

std::string show(Vec3 v);
std::string show(DVec3 v);
std::string show(const Ray& ray);

// Whether `distance` is one of the acceptable distances of `e`.
bool distance_ok(const Expectation& e, double distance);
// The expected normal for a hit at an acceptable `distance`.
DVec3 normal_for(const Expectation& e, double distance);

} // namespace shape_oracle

#pragma once
// What a correct Triangle::hit or Sphere::hit may answer for a ray: the exact answer for the float
// inputs (solved in double), and how far from it a correct float implementation can be, a
// forward-error bound that follows from the ray's conditioning (handout §2.4). Nothing here depends
// on how the reference rounds: the bound holds for every grouping of the formulas the handout
// allows (Cramer's triple products as on the slides, the n-form of §2.1, the stable or textbook
// quadratic of §2.2), so that any of them passes and a wrong formula (an edge missed by 1e-2, a
// distance off by a factor |dir|) does not.
//
// Where the bound does not decide (a ray within rounding, or the allowed edge slack, of an edge, the
// silhouette or an end of dist_bounds; a ray so nearly parallel to a triangle that the sign of its
// determinant is uncertain), either a hit or a miss is right, and a value that rounding could move
// anywhere is not checked.
#include "shapes.h"
#include "tri_mesh.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace task2 {

using DVec3 = glm::dvec3;

// Unit roundoff of float: every correctly rounded float operation has relative error <= 2^-24.
constexpr double FLOAT_EPS = 0x1p-24;
// The backward error allowed to a correct float implementation, in units of FLOAT_EPS: any grouping
// of Möller–Trumbore's triple products rounds at most 8 times along a path (shape_check.cpp), the
// stable quadratic about as often; twice that leaves room for a student's extra steps (1 / det,
// a normalized direction), and the textbook discriminant's cancellation is covered separately.
constexpr double ROUNDING = 16.0 * FLOAT_EPS;
// The largest barycentric slack (handout §2.3) the grader accepts: a hit at most this far outside
// an edge, in barycentric units, is not wrong; no slack at all is not wrong either. The reference
// uses 1e-5.
constexpr double MAX_EDGE_SLACK = 1e-4;

enum class Verdict { hit, miss, either };

// A hit a correct implementation may report: at distance t within t_error, with a unit normal
// within normal_error of `normal`. An infinite error: that value is not checked (rounding could
// move it anywhere).
struct Allowed_Hit {
	double t = 0.0, t_error = 0.0;
	DVec3 normal{0.0};
	double normal_error = 0.0;
};

struct Expectation {
	Verdict verdict = Verdict::miss;
	std::vector<Allowed_Hit> hits; // none for a miss
	std::string why;               // why the verdict is what it is, for messages
};

Expectation expect_hit(const Triangle& tri, const Ray& ray);
Expectation expect_hit(const Sphere& sphere, const Ray& ray);

// The nearer root of the sphere's quadratic for the ray (handout §2.2), solved in double, or NaN if
// the ray's line misses the sphere: what a numerically stable float solution must come close to.
double exact_near_root(const Sphere& sphere, const Ray& ray);

// Why `got` (the student's Triangle::hit or Sphere::hit for `ray`) does not meet `e`, or "" if it
// does: hit or miss, distance, position = ray.at(distance), unit normal, origin, dist_bounds.
// `section` names the handout section to read for the shape.
std::string hit_problem(const Expectation& e, const Trace& got, const Ray& ray, const char* section);

std::string show(Vec3 v);
std::string show(DVec3 v);
std::string show(const Ray& ray);

} // namespace task2

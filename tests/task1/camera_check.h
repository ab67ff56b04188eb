#pragma once
// Checking camera rays against the reference's (the judge links the reference task 1): the expected
// ray for a film point, the film point a direction came from, and the usual mistakes, each
// recognised as the reference's ray for a camera or film point changed the way the mistake changes
// it, and named in the handout's terms.
#include "camera.h"

#include <glm/glm.hpp>

#include <string>

namespace task1 {

using DVec2 = glm::dvec2;
using DVec3 = glm::dvec3;

std::string show(DVec3 v);
double radians(double degrees);
double degrees(double radians);

inline bool near(DVec3 a, DVec3 b, double tolerance) {
	return glm::length(a - b) <= tolerance;
}

// Tolerance for a direction computed in float from O(1) inputs: each component is within a few
// float ulps (~1e-7) of the exact value; 1e-5 leaves a wide margin, while every mistake recognised
// below moves some tested direction by more than 1e-2.
constexpr double DIRECTION_TOLERANCE = 1e-5;

// The reference's ray through film_uv, in double precision.
DVec3 expected_direction(const Camera& camera, DVec2 film_uv);
DVec3 expected_origin(const Camera& camera);

// The film point a world direction (any length) passes through: the plane of the reference's rays
// through three film points, and where `dir` crosses it.
class Film_Plane {
public:
	explicit Film_Plane(const Camera& camera);
	DVec2 film_uv(DVec3 dir) const;

private:
	DVec3 forward, corner, u_axis, v_axis; // on the plane dot(p, forward) = 1
};

// Why `got` is not the ray through film_uv, in the handout's terms ("" if it is right).
std::string ray_problem(const Camera& camera, DVec2 film_uv, const Ray& got);

} // namespace task1

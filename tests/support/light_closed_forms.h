#pragma once
// Closed forms for direct lighting, in double precision and independent of the
// framework's light code: the oracles of tests/framework/test_area_lights.cpp and the task 6 grader.
#include <glm/glm.hpp>

#include <vector>

namespace closed_form {

using DVec3 = glm::dvec3;

// Irradiance at `point` (unit normal `normal`) from a planar polygon of uniform radiance L that lies
// entirely above the point's horizon, by Lambert's formula:
//     E = (L / 2) * sum_i Theta_i * (n . Gamma_i),
// Theta_i the angle subtended at the point by edge (v_i, v_i+1) and Gamma_i the unit normal of the
// plane through the point and that edge. Either winding of the polygon gives the same E.
double polygon_irradiance(const std::vector<DVec3>& polygon, DVec3 point, DVec3 normal, double radiance);

// The special case of a square of half-side a, parallel to the receiver at height h and centred
// above it: with x = a / h, E = 4 L * x / sqrt(1 + x^2) * atan(x / sqrt(1 + x^2))
// (a / h = 0.5 -> 0.752275 L; a / h = 1 -> 1.740840 L).
double centred_square_irradiance(double half_side, double height, double radiance);

// Irradiance from a sphere of radiance L and radius r whose centre is at distance d, in a direction
// at angle beta from the normal, the whole sphere above the horizon: E = pi L (r / d)^2 cos(beta).
double sphere_irradiance(double radius, double distance, double cos_beta, double radiance);

// Solid angle of triangle (a, b, c) seen from `point` (Van Oosterom and Strackee 1983): with the
// vertices relative to the point,
//     tan(Omega / 2) = |a . (b x c)| / (|a||b||c| + (a . b)|c| + (a . c)|b| + (b . c)|a|).
double triangle_solid_angle(DVec3 a, DVec3 b, DVec3 c, DVec3 point);

// Solid angle of a sphere of radius r whose centre is at distance d > r: 2 pi (1 - sqrt(1 - (r/d)^2)).
double sphere_solid_angle(double radius, double distance);

} // namespace closed_form

#pragma once
// Directions, angles and printing shared by the task-5 tests.
#include "vec_math.h"
#include "rng.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

namespace task5 {

constexpr double PI = 3.14159265358979323846;

// The unit direction at polar angle theta (degrees) from +y (or from -y when below) and azimuth phi.
inline Vec3 direction(double theta_degrees, double phi, bool below = false) {
	double t = theta_degrees * PI / 180.0;
	double y = below ? -std::cos(t) : std::cos(t);
	return Vec3{float(std::sin(t) * std::cos(phi)), float(y), float(std::sin(t) * std::sin(phi))};
}

inline std::string str(Vec3 v) {
	return "(" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + ")";
}

// Inside glass of index `ior`, directions further than this from the normal are totally reflected:
// sin(theta_c) = 1 / ior (41.81 degrees for 1.5).
inline double critical_angle_degrees(double ior) {
	return std::asin(1.0 / ior) * 180.0 / PI;
}

// ---- The exact answers for float inputs, in double (never the reference's float answer) ----

// The refracted direction of Snell's law for `out` (local frame, +y the normal; out.y > 0 outside,
// in vacuum, against glass of index `ior`), or nothing at total internal reflection (handout §5.2).
inline std::optional<glm::dvec3> exact_refraction(Vec3 out, double ior) {
	glm::dvec3 o(out);
	o /= glm::length(o);
	bool outside = o.y > 0.0;
	double eta = outside ? 1.0 / ior : ior;
	double cos2_in = 1.0 - eta * eta * (o.x * o.x + o.z * o.z);
	if (cos2_in < 0.0) return std::nullopt;
	double cos_in = std::sqrt(cos2_in);
	return glm::dvec3{-eta * o.x, outside ? -cos_in : cos_in, -eta * o.z};
}

// The exact unpolarised Fresnel reflectance F = (r_s^2 + r_p^2) / 2 for cos_theta (> 0 outside) and
// an index of refraction (handout §5.3); 1 at total internal reflection.
inline double exact_fresnel(double cos_theta, double ior) {
	bool outside = cos_theta > 0.0;
	double n_i = outside ? 1.0 : ior, n_t = outside ? ior : 1.0;
	double cos_i = std::min(1.0, std::abs(cos_theta));
	double sin2_t = (n_i / n_t) * (n_i / n_t) * (1.0 - cos_i * cos_i);
	if (sin2_t >= 1.0) return 1.0;
	double cos_t = std::sqrt(1.0 - sin2_t);
	double r_s = (n_i * cos_i - n_t * cos_t) / (n_i * cos_i + n_t * cos_t);
	double r_p = (n_t * cos_i - n_i * cos_t) / (n_t * cos_i + n_i * cos_t);
	return 0.5 * (r_s * r_s + r_p * r_p);
}

// ---- Inputs drawn from a grading seed ----

inline double uniform(RNG& rng, double lo, double hi) {
	return lo + (hi - lo) * double(rng.unit());
}

// An index of refraction between water-like and diamond-like glass.
inline float random_ior(RNG& rng) {
	return float(uniform(rng, 1.2, 2.4));
}

inline double random_azimuth(RNG& rng) {
	return uniform(rng, 0.0, 2.0 * PI);
}

} // namespace task5

#pragma once
// Directions, angles and printing shared by the task-5 tests.
#include "vec_math.h"
#include "rng.h"

#include <cmath>
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

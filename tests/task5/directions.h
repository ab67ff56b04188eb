#pragma once
// Directions and printing shared by the task-5 tests.
#include "math.h"

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

} // namespace task5

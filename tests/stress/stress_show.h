#pragma once
// Vectors and rays as text with nine significant digits, for the stress tests' messages.
#include "ray.h"

#include <sstream>
#include <string>

namespace stress {

inline std::string show(Vec3 v) {
	std::ostringstream out;
	out.precision(9);
	out << "(" << v.x << ", " << v.y << ", " << v.z << ")";
	return out.str();
}

inline std::string show(const Ray& ray) {
	std::ostringstream out;
	out.precision(9);
	out << "point " << show(ray.point) << ", dir " << show(ray.dir) << ", dist_bounds [" << ray.dist_bounds.x << ", "
	    << ray.dist_bounds.y << "]";
	return out.str();
}

} // namespace stress

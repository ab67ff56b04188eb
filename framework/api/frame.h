#pragma once
#include "vec_math.h"

// An orthonormal shading frame. Local coordinates have the surface normal along +y, as every BSDF
// in the lab expects: a local direction w has cos(theta) = w.y.
struct Frame {
	// Any frame whose y axis is the unit vector n. Construction without branches on the sign of n
	// (Duff et al. 2017, "Building an Orthonormal Basis, Revisited", JCGT 6(1)).
	static Frame from_normal(Vec3 n) {
		float sign = std::copysign(1.0f, n.z);
		float a = -1.0f / (sign + n.z);
		float b = n.x * n.y * a;
		Frame f;
		f.x = Vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
		f.y = n;
		f.z = Vec3(b, sign + n.y * n.y * a, -n.y);
		return f;
	}

	Vec3 to_local(Vec3 w) const {
		return Vec3(glm::dot(w, x), glm::dot(w, y), glm::dot(w, z));
	}
	Vec3 to_world(Vec3 w) const {
		return w.x * x + w.y * y + w.z * z;
	}

	Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
};

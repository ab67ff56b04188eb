#pragma once
#include "vec_math.h"

// The hit record ("Trace") that every intersection routine returns.
struct Trace {
	bool hit = false;
	float distance = 0.0f; // the ray parameter t of the hit (see ray.h)
	Vec3 position;         // ray.at(distance)
	Vec3 normal;           // unit shading normal (interpolated on triangles), in the ray's space
	Vec3 origin;           // the ray's origin, ray.point

	// Filled in by the framework when the hit is in a scene (not by Triangle/Sphere::hit).
	uint32_t object = 0;   // index of the scene object that was hit
	uint32_t material = 0; // index of its material in Scene::materials

	// The closer of two records; a miss is farther than any hit.
	static Trace min(const Trace& a, const Trace& b) {
		if (!a.hit) return b;
		if (!b.hit) return a;
		return a.distance <= b.distance ? a : b;
	}
};

#pragma once
#include "bbox.h"
#include "trace.h"

// A sphere of `radius` centred at the origin of its local space (objects move it with their
// transform, see instance.h).
struct Sphere {
	// Task 2 (student/task2_shapes.cpp): closest hit with t in ray.dist_bounds. `ray` is in the
	// sphere's local space and ray.dir may have ANY non-zero length. Normal: unit, pointing outwards.
	Trace hit(const Ray& ray) const;

	BBox bbox() const {
		return BBox(Vec3{-radius}, Vec3{radius});
	}

	float radius = 1.0f;
};

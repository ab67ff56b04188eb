#pragma once
#include "ray.h"

#include <algorithm>

// Axis-aligned bounding box. A default-constructed box is empty (min = +inf, max = -inf), so
// enclosing anything into it gives that thing's box.
struct BBox {
	BBox() = default;
	BBox(Vec3 min, Vec3 max) : min(min), max(max) {
	}

	void enclose(Vec3 point) {
		min = glm::min(min, point);
		max = glm::max(max, point);
	}
	void enclose(const BBox& box) {
		min = glm::min(min, box.min);
		max = glm::max(max, box.max);
	}
	Vec3 center() const {
		return 0.5f * (min + max);
	}
	bool empty() const {
		return !(min.x <= max.x && min.y <= max.y && min.z <= max.z);
	}
	// Surface area 2(xy + yz + zx); 0 for an empty box. Flat boxes (one extent 0) are not empty.
	float surface_area() const {
		if (empty()) return 0.0f;
		Vec3 e = max - min;
		return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
	}

	// Task 3 (student/task3_bvh.cpp): slab test.
	// On entry `times` is the interval of t still of interest (e.g. ray.dist_bounds). Returns
	// whether the ray overlaps the box for some t in that interval, and if so narrows `times` to
	// the overlap [t_enter, t_exit]. Boxes may be flat; the ray may start inside the box.
	bool hit(const Ray& ray, Vec2& times) const;

	Vec3 min{INF_F};
	Vec3 max{-INF_F};
};

#pragma once
#include "vec_math.h"

// A ray r(t) = point + t * dir.
//
// `dir` need not have unit length: rays transformed into an object's local space are scaled.
// Hit distances are always measured in the ray parameter t, so a hit found in local space has the
// same t as in world space. For rays made by the camera or the path tracer, dir is unit length and
// t is the Euclidean distance.
struct Ray {
	Ray() = default;
	Ray(Vec3 point, Vec3 dir, Vec2 dist_bounds = Vec2{0.0f, INF_F}, uint32_t depth = 0)
		: point(point), dir(dir), dist_bounds(dist_bounds), depth(depth) {
	}

	Vec3 at(float t) const {
		return point + t * dir;
	}

	Vec3 point;
	Vec3 dir;
	// A hit counts only when dist_bounds.x <= t <= dist_bounds.y. So that a new ray cannot hit the
	// surface it leaves, a path starts it a little off that surface along the normal, with .x = 0
	// (spawn_ray, spawn_ray.h; handout §4.2). A closest-hit search lowers .y as it goes.
	Vec2 dist_bounds{0.0f, INF_F};
	// How many times the path has scattered before this ray (the camera ray has depth 0).
	uint32_t depth = 0;
};

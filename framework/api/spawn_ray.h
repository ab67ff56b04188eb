#pragma once
// Leaving a surface (handout §4.2). hit.position is rounded to floats, so it lies slightly above or
// below the true surface, and a ray started there can hit the surface it leaves ("surface acne").
// Every ray that continues a path therefore starts from the hit point moved off the surface, along
// the normal, to the side the ray leaves on, by a distance that grows with the rounding error of
// the point's coordinates: (1 + max |p_i|) * RAY_EPSILON, about 4e-6 near the origin and 0.04 at
// 10^4 (the scheme of Mitsuba 3's RayEpsilon, with a smaller factor; the stress suite, §4.5).
// Moving the origin, rather than raising dist_bounds.x, also protects grazing directions, which
// stay close to the surface long after any t_min.
#include "ray.h"
#include "trace.h"

#include <algorithm>
#include <cmath>

constexpr float RAY_EPSILON = 64.0f * 0x1p-24f;

// How far a ray leaving the point p starts from it.
inline float ray_offset(Vec3 p) {
	float magnitude = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
	return (1.0f + magnitude) * RAY_EPSILON;
}

// hit.position moved ray_offset off the surface, along the normal on the side `dir` points to.
inline Vec3 lifted(const Trace& hit, Vec3 dir) {
	Vec3 side = glm::dot(dir, hit.normal) >= 0.0f ? hit.normal : -hit.normal;
	return hit.position + ray_offset(hit.position) * side;
}

// The ray that continues a path from `hit` in direction `dir`: from lifted(hit, dir), free to hit
// anything from there on (dist_bounds = {0, INF_F}), at the given depth.
inline Ray spawn_ray(const Trace& hit, Vec3 dir, uint32_t depth) {
	return Ray(lifted(hit, dir), dir, Vec2{0.0f, INF_F}, depth);
}

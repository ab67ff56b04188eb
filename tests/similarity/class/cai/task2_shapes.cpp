// Task 2: intersecting primitives. Handout: handouts/task2_shapes.md
#include "shapes.h"
#include "tri_mesh.h"

namespace {
struct Barycentric {
	float u, v;
	bool inside(float eps) const { return u >= -eps && v >= -eps && u + v <= 1.0f + eps; }
	float w() const { return 1.0f - u - v; }
};

Trace make_hit(const Ray& r, float t, Vec3 n) {
	Trace h;
	h.origin = r.point;
	h.hit = true;
	h.distance = t;
	h.position = r.at(t);
	h.normal = glm::normalize(n);
	return h;
}

Trace make_miss(const Ray& r) {
	Trace h;
	h.origin = r.point;
	return h;
}

bool in_range(Vec2 bounds, float t) {
	return bounds.x <= t && t <= bounds.y && t != INF_F;
}
} // namespace

Trace Triangle::hit(const Ray& r) const {
	Vec3 a = v1.position - v0.position, b = v2.position - v0.position;
	// exact zero-area test
	if (a.x * b.y == a.y * b.x && a.y * b.z == a.z * b.y && a.z * b.x == a.x * b.z) return make_miss(r);
	Vec3 geo_n = glm::cross(a, b);
	Vec3 rel = r.point - v0.position;
	float denom = glm::dot(r.dir, geo_n);
	if (denom == 0.0f) return make_miss(r);
	float f = -1.0f / denom;
	Barycentric bc{glm::dot(r.dir, glm::cross(b, rel)) * f, glm::dot(r.dir, glm::cross(rel, a)) * f};
	float t = glm::dot(rel, geo_n) * f;
	if (bc.inside(1e-5f) && in_range(r.dist_bounds, t)) {
		return make_hit(r, t, bc.w() * v0.normal + bc.u * v1.normal + bc.v * v2.normal);
	}
	return make_miss(r);
}

Trace Sphere::hit(const Ray& r) const {
	float dd = glm::dot(r.dir, r.dir);
	float od = glm::dot(r.point, r.dir);
	float oo_rr = glm::dot(r.point, r.point) - radius * radius;
	float dist_to_line = glm::length(r.point - r.dir * (od / dd));
	float disc = dd * (radius - dist_to_line) * (radius + dist_to_line);
	if (disc > 0.0f && disc < INF_F) {
		float sq = std::sqrt(disc);
		float q = od < 0.0f ? sq - od : -sq - od;
		float r1 = q / dd, r2 = oo_rr / q;
		float first = std::min(r1, r2), second = std::max(r1, r2);
		float t = in_range(r.dist_bounds, first) ? first : second;
		if (in_range(r.dist_bounds, t)) {
			Vec3 n = r.at(t) / radius;
			if (n != Vec3{0.0f}) return make_hit(r, t, n);
		}
	}
	return make_miss(r);
}

// Task 2: intersecting primitives. Handout: handouts/task2_shapes.md
#include "shapes.h"
#include "tri_mesh.h"

#include <cmath>

namespace {
// Roots of a t^2 + 2 b t + c = 0 with the stable formulas (handout 2.2), smaller first.
// disc is b^2 - a c, computed by the caller without cancellation.
bool solve_quadratic(float a, float b, float c, float disc, float& t_lo, float& t_hi) {
	if (!(disc > 0.0f && disc < INF_F)) return false;
	float q = -(b + std::copysign(std::sqrt(disc), b));
	t_lo = std::fmin(q / a, c / q);
	t_hi = std::fmax(q / a, c / q);
	return true;
}
} // namespace

Trace Triangle::hit(const Ray& ray) const {
	Trace tr;
	tr.origin = ray.point;
	const Vec3& A = v0.position;
	const Vec3& B = v1.position;
	const Vec3& C = v2.position;
	Vec3 edge1 = B - A, edge2 = C - A;
	bool degenerate = edge1.y * edge2.z == edge1.z * edge2.y && edge1.z * edge2.x == edge1.x * edge2.z &&
	                  edge1.x * edge2.y == edge1.y * edge2.x;
	if (degenerate) return tr;
	Vec3 normal = glm::cross(edge1, edge2);
	float D = -glm::dot(ray.dir, normal);
	if (D == 0.0f) return tr;
	Vec3 toOrigin = ray.point - A;
	float inv = 1.0f / D;
	float t = glm::dot(toOrigin, normal) * inv;
	if (!(t >= ray.dist_bounds.x && t <= ray.dist_bounds.y && std::isfinite(t))) return tr;
	float b1 = glm::dot(ray.dir, glm::cross(edge2, toOrigin)) * inv;
	if (!(b1 >= -1e-5f)) return tr;
	float b2 = glm::dot(ray.dir, glm::cross(toOrigin, edge1)) * inv;
	if (!(b2 >= -1e-5f && b1 + b2 <= 1.0f + 1e-5f)) return tr;
	float b0 = 1.0f - b1 - b2;
	tr.hit = true;
	tr.distance = t;
	tr.position = ray.at(t);
	tr.normal = glm::normalize(b0 * v0.normal + b1 * v1.normal + b2 * v2.normal);
	return tr;
}

Trace Sphere::hit(const Ray& ray) const {
	Trace tr;
	tr.origin = ray.point;
	float a = glm::dot(ray.dir, ray.dir);
	float b = glm::dot(ray.point, ray.dir);
	float c = glm::dot(ray.point, ray.point) - radius * radius;
	Vec3 closest = ray.point - (b / a) * ray.dir; // the point of the line nearest to the centre
	float dist = glm::length(closest);
	float t_lo, t_hi;
	if (!solve_quadratic(a, b, c, a * (radius - dist) * (radius + dist), t_lo, t_hi)) return tr;
	for (float t : {t_lo, t_hi}) {
		if (t >= ray.dist_bounds.x && t <= ray.dist_bounds.y && std::isfinite(t)) {
			Vec3 out = ray.at(t) / radius;
			if (glm::length(out) == 0.0f) return tr;
			tr.hit = true;
			tr.distance = t;
			tr.position = ray.at(t);
			tr.normal = glm::normalize(out);
			return tr;
		}
	}
	return tr;
}

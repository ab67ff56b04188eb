// Task 2: intersecting primitives. Handout: handouts/task2_shapes.md
#include "shapes.h"
#include "tri_mesh.h"

Trace Triangle::hit(const Ray& ray) const {
	Trace out;
	out.origin = ray.point;

	Vec3 p0 = v0.position;
	Vec3 e1 = v1.position - p0;
	Vec3 e2 = v2.position - p0;
	Vec3 d = ray.dir;
	Vec3 s = ray.point - p0;

	// collinear vertices: the cross product is exactly zero
	float nx1 = e1.y * e2.z, nx2 = e1.z * e2.y;
	float ny1 = e1.z * e2.x, ny2 = e1.x * e2.z;
	float nz1 = e1.x * e2.y, nz2 = e1.y * e2.x;
	if (nx1 == nx2 && ny1 == ny2 && nz1 == nz2) {
		return out;
	}

	Vec3 n = glm::cross(e1, e2);
	float det = -glm::dot(d, n);
	if (det == 0.0f) {
		return out;
	}

	float u = glm::dot(d, glm::cross(e2, s)) / det;
	float v = glm::dot(d, glm::cross(s, e1)) / det;
	float t = glm::dot(s, n) / det;

	const float eps = 1e-5f;
	if (u >= -eps && v >= -eps && u + v <= 1.0f + eps && t >= ray.dist_bounds.x && t <= ray.dist_bounds.y &&
	    t < INF_F) {
		out.hit = true;
		out.distance = t;
		out.position = ray.at(t);
		Vec3 smooth = v0.normal * (1.0f - u - v) + v1.normal * u + v2.normal * v;
		out.normal = glm::normalize(smooth);
	}
	return out;
}

Trace Sphere::hit(const Ray& ray) const {
	Trace out;
	out.origin = ray.point;

	float a = glm::dot(ray.dir, ray.dir);
	float half_b = glm::dot(ray.point, ray.dir);
	float c = glm::dot(ray.point, ray.point) - radius * radius;

	float l = glm::length(ray.point - ray.dir * (half_b / a));
	float disc = a * (radius - l) * (radius + l);
	if (!(disc > 0.0f) || disc == INF_F) {
		return out;
	}

	float sign = half_b >= 0.0f ? 1.0f : -1.0f;
	float q = -(half_b + sign * std::sqrt(disc));
	float roots[2] = {q / a, c / q};
	if (roots[1] < roots[0]) {
		std::swap(roots[0], roots[1]);
	}

	for (int i = 0; i < 2; i++) {
		float t = roots[i];
		if (t >= ray.dist_bounds.x && t <= ray.dist_bounds.y && t < INF_F) {
			Vec3 n = ray.at(t) / radius;
			if (n.x == 0.0f && n.y == 0.0f && n.z == 0.0f) {
				return out;
			}
			out.hit = true;
			out.distance = t;
			out.position = ray.at(t);
			out.normal = glm::normalize(n);
			return out;
		}
	}
	return out;
}

// Task 2: intersecting primitives. Handout: handouts/task2_shapes.md
#include "shapes.h"
#include "tri_mesh.h"

namespace {
const float SLACK = 1e-5f; // handout 2.3: shared edges

Trace no_hit(const Ray& ray) {
	Trace t;
	t.origin = ray.point;
	return t;
}

bool within(const Ray& ray, float t) {
	return t >= ray.dist_bounds.x && t <= ray.dist_bounds.y && t < INF_F;
}

bool zero_area(Vec3 a, Vec3 b) {
	// compare the products, not the cross product (FMA, handout 2.3)
	return a.y * b.z == a.z * b.y && a.z * b.x == a.x * b.z && a.x * b.y == a.y * b.x;
}
} // namespace

Trace Triangle::hit(const Ray& ray) const {
	Vec3 e1 = v1.position - v0.position;
	Vec3 e2 = v2.position - v0.position;
	if (zero_area(e1, e2)) return no_hit(ray);
	Vec3 n = glm::cross(e1, e2);
	Vec3 s = ray.point - v0.position;
	float det = -glm::dot(ray.dir, n);
	if (det == 0.0f) return no_hit(ray);
	float u = glm::dot(ray.dir, glm::cross(e2, s)) / det;
	float v = glm::dot(ray.dir, glm::cross(s, e1)) / det;
	float t = glm::dot(s, n) / det;
	bool inside = u >= -SLACK && v >= -SLACK && u + v <= 1.0f + SLACK;
	if (!(inside && within(ray, t))) return no_hit(ray);
	Trace result = no_hit(ray);
	result.hit = true;
	result.distance = t;
	result.position = ray.at(t);
	result.normal = glm::normalize((1.0f - u - v) * v0.normal + u * v1.normal + v * v2.normal);
	return result;
}

Trace Sphere::hit(const Ray& ray) const {
	Vec3 o = ray.point;
	Vec3 d = ray.dir;
	float a = glm::dot(d, d);
	float b = glm::dot(o, d);
	float c = glm::dot(o, o) - radius * radius;
	float l = glm::length(o - d * (b / a));
	float delta = a * (radius - l) * (radius + l);
	if (!(delta > 0.0f) || !(delta < INF_F)) return no_hit(ray);
	float root = std::sqrt(delta);
	float q = b > 0.0f ? -(b + root) : -(b - root);
	float near = q / a;
	float far = c / q;
	if (near > far) {
		float tmp = near;
		near = far;
		far = tmp;
	}
	float t;
	if (within(ray, near)) {
		t = near;
	} else if (within(ray, far)) {
		t = far;
	} else {
		return no_hit(ray);
	}
	Vec3 p = ray.at(t);
	Vec3 scaled = p / radius;
	if (scaled == Vec3{0.0f}) return no_hit(ray);
	Trace result = no_hit(ray);
	result.hit = true;
	result.distance = t;
	result.position = p;
	result.normal = glm::normalize(scaled);
	return result;
}

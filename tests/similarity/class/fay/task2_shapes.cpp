// Task 2: intersecting primitives. Handout: handouts/task2_shapes.md
// (Planted for the similarity test: cai's task 2 with every name of its own changed, its helpers
// and its two functions in another order, and its comments replaced.)
#include "shapes.h"
#include "tri_mesh.h"

namespace {
bool t_ok(Vec2 range, float dist) {
	return range.x <= dist && dist <= range.y && dist != INF_F;
}

Trace empty_record(const Ray& ray) {
	Trace rec;
	rec.origin = ray.point;
	return rec;
}

Trace hit_record(const Ray& ray, float dist, Vec3 nrm) {
	Trace rec;
	rec.origin = ray.point;
	rec.hit = true;
	rec.distance = dist;
	rec.position = ray.at(dist);
	rec.normal = glm::normalize(nrm);
	return rec;
}

struct Weights {
	float alpha, beta;
	bool inside(float tol) const { return alpha >= -tol && beta >= -tol && alpha + beta <= 1.0f + tol; }
	float gamma() const { return 1.0f - alpha - beta; }
};
} // namespace

Trace Sphere::hit(const Ray& ray) const {
	float len2 = glm::dot(ray.dir, ray.dir);
	float proj = glm::dot(ray.point, ray.dir);
	float cterm = glm::dot(ray.point, ray.point) - radius * radius;
	float miss_dist = glm::length(ray.point - ray.dir * (proj / len2));
	float delta = len2 * (radius - miss_dist) * (radius + miss_dist);
	if (delta > 0.0f && delta < INF_F) {
		float root = std::sqrt(delta);
		float qq = proj < 0.0f ? root - proj : -root - proj;
		float ta = qq / len2, tb = cterm / qq;
		float lo = std::min(ta, tb), hi = std::max(ta, tb);
		float dist = t_ok(ray.dist_bounds, lo) ? lo : hi;
		if (t_ok(ray.dist_bounds, dist)) {
			Vec3 nrm = ray.at(dist) / radius;
			if (nrm != Vec3{0.0f}) return hit_record(ray, dist, nrm);
		}
	}
	return empty_record(ray);
}

Trace Triangle::hit(const Ray& ray) const {
	Vec3 side1 = v1.position - v0.position, side2 = v2.position - v0.position;
	// degenerate?
	if (side1.x * side2.y == side1.y * side2.x && side1.y * side2.z == side1.z * side2.y &&
	    side1.z * side2.x == side1.x * side2.z)
		return empty_record(ray);
	Vec3 face = glm::cross(side1, side2);
	Vec3 offset = ray.point - v0.position;
	float dn = glm::dot(ray.dir, face);
	if (dn == 0.0f) return empty_record(ray);
	float scale = -1.0f / dn;
	Weights w{glm::dot(ray.dir, glm::cross(side2, offset)) * scale, glm::dot(ray.dir, glm::cross(offset, side1)) * scale};
	float dist = glm::dot(offset, face) * scale;
	if (w.inside(1e-5f) && t_ok(ray.dist_bounds, dist)) {
		return hit_record(ray, dist, w.gamma() * v0.normal + w.alpha * v1.normal + w.beta * v2.normal);
	}
	return empty_record(ray);
}

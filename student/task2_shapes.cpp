// Task 2: intersecting primitives. Handout: handouts/task2_shapes.md
#include "shapes.h"
#include "tri_mesh.h"

namespace {
// Your helper functions go here. The anonymous namespace keeps them private to this file: two task
// files that each define a helper of the same name (say `lerp`) would otherwise not link together.
} // namespace

Trace Triangle::hit(const Ray& ray) const {
	// TODO (Task 2, handout §2.1): Möller–Trumbore ray-triangle intersection.
	// - Solve o + t d = (1 - u - v) p0 + u p1 + v p2 for (u, v, t) with Cramer's rule.
	// - The hit counts only if u >= 0, v >= 0, u + v <= 1 and t lies in ray.dist_bounds (both ends
	//   included). Write these tests positively, if (!(... && ...)) return a miss, so that NaN
	//   fails them (handout §2.3).
	// - position: ray.at(t) may help. normal: interpolate v0/v1/v2.normal with the barycentric
	//   coordinates (1 - u - v, u, v), then normalize. Both faces are hit; do not flip the normal.
	// - A ray parallel to the triangle (det == 0), or a triangle of zero area, never hits (and
	//   never gives NaN). Tiny triangles have tiny determinants: no |det| < epsilon test.
	// - Rays through an edge shared by two triangles must hit one of them: accept u, v and
	//   1 - u - v down to -1e-5 (handout §2.3).
	Trace ret;
	ret.origin = ray.point;
	ret.hit = false;
	ret.distance = 0.0f;
	ret.position = Vec3{};
	ret.normal = Vec3{};
	return ret;
}

Trace Sphere::hit(const Ray& ray) const {
	// TODO (Task 2, handout §2.2): ray-sphere intersection in the sphere's local space, where the
	// sphere is centred at the origin with this->radius.
	// - Substitute r(t) = o + t d into |x|^2 = radius^2 and solve the quadratic for t.
	// - Warning: ray.dir is NOT unit length here (objects scale rays into local space), and t must
	//   stay in the ray's own parameter.
	// - Use the numerically stable discriminant and roots of handout §2.2: the textbook
	//   b^2 - 4ac misses small or distant spheres.
	// - Return the closest root inside ray.dist_bounds: if the near root is outside the bounds,
	//   the far one may still count (e.g. when the ray starts inside the sphere).
	// - normal: unit, pointing away from the centre. Tangent rays: no NaN (handout §2.3).
	Trace ret;
	ret.origin = ray.point;
	ret.hit = false;
	ret.distance = 0.0f;
	ret.position = Vec3{};
	ret.normal = Vec3{};
	return ret;
}

#include "bvh_test_scenes.h"

#include "judge.h"
#include "obj_loader.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cstdio>
#include <cstring>

namespace {

Vec3 uniform_in_cube(RNG& rng) {
	return Vec3{rng.unit(), rng.unit(), rng.unit()} * 2.0f - 1.0f;
}

// Uniform on the unit sphere: z uniform in [-1, 1], azimuth uniform.
Vec3 uniform_direction(RNG& rng) {
	float z = 1.0f - 2.0f * rng.unit(), phi = 2.0f * PI_F * rng.unit();
	float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
	return Vec3{r * std::cos(phi), r * std::sin(phi), z};
}

Vec3 uniform_in_box(RNG& rng, const BBox& box) {
	return box.min + Vec3{rng.unit(), rng.unit(), rng.unit()} * (box.max - box.min);
}

// Direction lengths vary: rays in an object's local space are scaled.
float random_length(RNG& rng) {
	return std::exp2(4.0f * rng.unit() - 2.0f); // in [1/4, 4)
}

bool same_bits(float a, float b) {
	return std::memcmp(&a, &b, sizeof a) == 0;
}

bool same_bits(Vec3 a, Vec3 b) {
	return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z);
}

std::string describe(Vec3 v) {
	char text[96];
	std::snprintf(text, sizeof text, "(%.9g, %.9g, %.9g)", double(v.x), double(v.y), double(v.z));
	return text;
}

std::string describe(const Trace& trace) {
	if (!trace.hit) return "a miss";
	char text[48];
	std::snprintf(text, sizeof text, "a hit at t = %.9g", double(trace.distance));
	return text + (", position " + describe(trace.position) + ", normal " + describe(trace.normal));
}

// How much farther than the closest hit a correct BVH::hit may return one. A triangle lies inside
// its leaf's box, so its true t is at least the box's true entry t; but the slab test computes the
// entry t with 2 roundings and Triangle::hit the triangle's with at most 14 on the way to t
// (Möller–Trumbore), so a box whose computed entry lies just beyond the closest hit so far may be
// skipped although a triangle in it is hit nearer, by up to (gamma_2 + gamma_14) t without
// cancellation, gamma_n = n u / (1 - n u), u = 2^-24 (Higham, Accuracy and Stability of Numerical
// Algorithms, §3.1). A BVH that skips it returns the next hit instead. So: gamma_16, relative.
constexpr double ROUNDING_SLACK = 16.0 * 0x1p-24 / (1.0 - 16.0 * 0x1p-24);

struct Brute_Force_Hit {
	Trace closest;
	std::vector<Trace> near; // every hit within ROUNDING_SLACK of the closest, the closest included
};

// What a student should check for one kind of disagreement.
std::string diagnosis(const Trace& got, const Brute_Force_Hit& expected) {
	if (!got.hit)
		return "BVH::hit missed a triangle that brute force hits: check that BBox::hit accepts flat boxes, rays "
		       "starting inside, and direction components of 0 (handout §3.1), and that the traversal visits every "
		       "child whose box the ray enters before the closest hit so far (§3.3)";
	if (!expected.closest.hit || got.distance < expected.closest.distance)
		return "BVH::hit returned a hit that no triangle has within ray.dist_bounds: return only what the "
		       "primitives' hit() report, with the ray's own bounds (§3.3)";
	if (got.distance > expected.closest.distance)
		return "BVH::hit returned a farther hit than the closest one: a child was skipped although its box starts "
		       "before the closest hit so far, or the closest hit was not kept (§3.3)";
	return "BVH::hit returned the right distance but not the record of a triangle hit there: keep the whole "
	       "Trace of the closest primitive hit (§3.3)";
}

} // namespace

Triangle make_triangle(RNG& rng, Vec3 a, Vec3 b, Vec3 c) {
	return Triangle{{a, uniform_direction(rng)}, {b, uniform_direction(rng)}, {c, uniform_direction(rng)}};
}

std::vector<Triangle> random_soup(RNG& rng, size_t count, float size) {
	std::vector<Triangle> triangles;
	for (size_t i = 0; i < count; i++) {
		Vec3 centre = uniform_in_cube(rng);
		triangles.push_back(make_triangle(rng, centre + size * uniform_direction(rng), centre + size * uniform_direction(rng),
		                                  centre + size * uniform_direction(rng)));
	}
	return triangles;
}

std::vector<Triangle> clustered_soup(RNG& rng) {
	std::vector<Triangle> triangles;
	// Clusters of 50..400 triangles with radii 0.01..0.1, far apart relative to their size.
	for (int cluster = 0; cluster < 24; cluster++) {
		Vec3 centre = 10.0f * uniform_in_cube(rng);
		float radius = 0.01f * std::exp2(3.3f * rng.unit());
		size_t count = 50 + rng.integer(350);
		for (size_t i = 0; i < count; i++) {
			Vec3 p = centre + radius * uniform_in_cube(rng);
			float size = 0.2f * radius;
			triangles.push_back(make_triangle(rng, p + size * uniform_direction(rng), p + size * uniform_direction(rng),
			                                  p + size * uniform_direction(rng)));
		}
	}
	// A few large triangles across the scene.
	for (int i = 0; i < 12; i++)
		triangles.push_back(make_triangle(rng, 10.0f * uniform_in_cube(rng), 10.0f * uniform_in_cube(rng),
		                                  10.0f * uniform_in_cube(rng)));
	return triangles;
}

std::vector<Triangle> planar_grid(RNG& rng, int n) {
	std::vector<Triangle> triangles;
	for (int i = 0; i < n; i++) {
		for (int j = 0; j < n; j++) {
			Vec3 p00{float(i), float(j), 0.0f}, p10{float(i + 1), float(j), 0.0f};
			Vec3 p01{float(i), float(j + 1), 0.0f}, p11{float(i + 1), float(j + 1), 0.0f};
			triangles.push_back(make_triangle(rng, p00, p10, p11));
			triangles.push_back(make_triangle(rng, p00, p11, p01));
		}
	}
	return triangles;
}

std::vector<Ray> random_rays(RNG& rng, const BBox& box, const std::vector<Triangle>& triangles, size_t count) {
	Vec3 centre = box.center();
	float radius = glm::length(box.max - box.min);
	std::vector<Ray> rays;
	for (size_t i = 0; i < count; i++) {
		switch (i % 8) {
		case 0:
		case 1:
		case 2: { // from outside, towards a random point of the box
			Vec3 origin = centre + radius * uniform_direction(rng);
			rays.emplace_back(origin, random_length(rng) * (uniform_in_box(rng, box) - origin));
			break;
		}
		case 3:
		case 4: // from inside, in any direction
			rays.emplace_back(uniform_in_box(rng, box), random_length(rng) * uniform_direction(rng));
			break;
		case 5: { // a bounded interval around a random target point (reached at t = 1)
			Vec3 origin = centre + radius * uniform_direction(rng);
			Vec2 bounds{1.0f - 0.5f * rng.unit(), 1.0f + 0.5f * rng.unit()};
			rays.emplace_back(origin, uniform_in_box(rng, box) - origin, bounds);
			break;
		}
		default: { // axis-aligned, along the lines where the planes of triangles' boxes meet
			int axis = int(rng.integer(3));
			Vec3 origin, dir{rng.coin_flip(0.5f) ? 0.0f : -0.0f, rng.coin_flip(0.5f) ? 0.0f : -0.0f,
			                 rng.coin_flip(0.5f) ? 0.0f : -0.0f};
			for (int k = 0; k < 3; k++) {
				const Triangle& t = triangles[rng.integer(uint32_t(triangles.size()))];
				const Tri_Mesh_Vert* vertex[3] = {&t.v0, &t.v1, &t.v2};
				origin[k] = vertex[rng.integer(3)]->position[k];
			}
			bool up = rng.coin_flip(0.5f);
			origin[axis] = up ? box.min[axis] - 0.5f * radius : box.max[axis] + 0.5f * radius;
			dir[axis] = up ? random_length(rng) : -random_length(rng);
			rays.emplace_back(origin, dir);
			break;
		}
		}
	}
	return rays;
}

BBox bounds_of(const std::vector<Triangle>& triangles) {
	BBox box;
	for (const Triangle& t : triangles) box.enclose(t.bbox());
	return box;
}

std::vector<BBox> boxes_of(const std::vector<Triangle>& triangles) {
	std::vector<BBox> boxes;
	for (const Triangle& t : triangles) boxes.push_back(t.bbox());
	return boxes;
}

namespace {

// The closest hit of one ray by testing every triangle, with every record near it.
Brute_Force_Hit brute_force(const std::vector<Triangle>& triangles, const Ray& ray) {
	Brute_Force_Hit result;
	std::vector<Trace> hits;
	for (const Triangle& t : triangles) {
		Trace trace = t.hit(ray);
		if (!trace.hit) continue;
		hits.push_back(trace);
		if (!result.closest.hit || trace.distance < result.closest.distance) result.closest = trace;
	}
	for (const Trace& trace : hits)
		if (double(trace.distance) <= double(result.closest.distance) * (1.0 + ROUNDING_SLACK)) result.near.push_back(trace);
	return result;
}

bool same_record(const Trace& a, const Trace& b) {
	if (!a.hit || !b.hit) return a.hit == b.hit;
	return same_bits(a.distance, b.distance) && same_bits(a.position, b.position) && same_bits(a.normal, b.normal);
}

} // namespace

Closest_Hits::Closest_Hits(const std::vector<Triangle>& triangles)
	: triangles(triangles), reference(std::vector<Triangle>(triangles), 4) {
}

size_t Closest_Hits::hitting(const std::vector<Ray>& rays) const {
	size_t count = 0;
	for (const Ray& ray : rays) count += reference.hit(ray).hit;
	return count;
}

std::string Closest_Hits::compare(const std::vector<Trace>& answers, const std::vector<Ray>& rays) const {
	size_t wrong = 0;
	std::string examples;
	for (size_t r = 0; r < rays.size(); r++) {
		const Trace& got = answers[r];
		if (same_record(got, reference.hit(rays[r]))) continue;
		Brute_Force_Hit want = brute_force(triangles, rays[r]);
		// The closest hit, a tie, or a hit nearly as close that rounding may put first.
		bool agree = !got.hit && !want.closest.hit;
		for (const Trace& near : want.near) agree = agree || (got.hit && same_record(got, near));
		if (agree) continue;
		if (++wrong <= 3)
			examples += "\n  ray " + describe(rays[r]) + ":\n    BVH::hit gave " + describe(got) +
			            ",\n    brute force gave " + describe(want.closest) + ".\n    " + diagnosis(got, want);
	}
	if (wrong == 0) return "";
	return std::to_string(wrong) + " of " + std::to_string(rays.size()) +
	       " rays disagree with brute force (first ones below)" + examples;
}

std::vector<Instance> triangle_instances(const std::vector<Triangle>& triangles) {
	std::vector<Instance> instances;
	for (size_t i = 0; i < triangles.size(); i++)
		instances.emplace_back(Tri_Mesh({triangles[i]}, 1), Mat4{1.0f}, 0u, uint32_t(i));
	return instances;
}

std::string describe(const Ray& ray) {
	char bounds[64];
	std::snprintf(bounds, sizeof bounds, "[%.9g, %.9g]", double(ray.dist_bounds.x), double(ray.dist_bounds.y));
	return "point " + describe(ray.point) + ", dir " + describe(ray.dir) + ", dist_bounds " + bounds;
}

uint64_t scene_seed(uint64_t public_seed) {
	std::optional<RNG> secret = judge::secret_inputs();
	return secret ? secret->integer() : public_seed;
}

std::vector<Triangle> load_placed_mesh(const std::string& path) {
	std::vector<Triangle> triangles = load_obj(path);
	std::optional<RNG> secret = judge::secret_inputs();
	if (!secret) return triangles;
	RNG& rng = *secret;
	Vec3 axis = glm::normalize(uniform_direction(rng) + Vec3{0.0f, 0.0f, 1e-3f});
	Mat4 to_world = glm::translate(Mat4{1.0f}, 4.0f * uniform_in_cube(rng)) *
	                glm::rotate(Mat4{1.0f}, 2.0f * PI_F * rng.unit(), axis) *
	                glm::scale(Mat4{1.0f}, Vec3{0.5f + 1.5f * rng.unit()});
	Mat3 normals = glm::transpose(glm::inverse(Mat3(to_world)));
	for (Triangle& t : triangles) {
		for (Tri_Mesh_Vert* v : {&t.v0, &t.v1, &t.v2}) {
			v->position = transform_point(to_world, v->position);
			v->normal = glm::normalize(normals * v->normal);
		}
	}
	return triangles;
}

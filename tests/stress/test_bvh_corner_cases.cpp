// Stress (handout §3): BVH::hit equals brute force where floating point and degenerate geometry
// bite: axis-aligned rays (1/0 = inf in the slab test), rays starting exactly on box faces and
// lying in them (0 * inf = NaN), flat boxes of planar walls, coincident centroids (a split that
// cannot separate anything), 10^6 identical triangles, and a tree dozens of levels deep.
#include "rng.h"
#include "stress_show.h"
#include "stress_count.h"
#include "stress_meshes.h"

#include "lab_catch2.h"

#include <cmath>
#include <functional>

namespace {

// The closest hit over all triangles, one by one.
Trace brute_force(const std::vector<Triangle>& tris, const Ray& ray) {
	Trace best;
	for (const Triangle& tri : tris) best = Trace::min(best, tri.hit(ray));
	return best;
}

// The closest hit over the triangles whose bounding box holds the hit point: hits accepted only by
// Triangle::hit's barycentric slack (handout §2.3) can lie just outside the triangle's box, where
// a BVH, whose boxes are tight, may or may not find them.
Trace brute_force_in_boxes(const std::vector<Triangle>& tris, const Ray& ray) {
	Trace best;
	for (const Triangle& tri : tris) {
		Trace t = tri.hit(ray);
		BBox box = tri.bbox();
		bool inside = t.hit && glm::all(glm::greaterThanEqual(t.position, box.min)) &&
		              glm::all(glm::lessThanEqual(t.position, box.max));
		if (inside) best = Trace::min(best, t);
	}
	return best;
}

bool same(const Trace& a, const Trace& b) {
	return a.hit == b.hit && (!a.hit || a.distance == b.distance);
}

// Counts rays on which the BVH and brute force disagree (hit or miss, or distance), allowing the
// BVH to skip hits that lie outside their triangle's box. Every query of the mesh counts: the
// framework's (Tri_Mesh::hit, through the fast accelerator), task 3's BVH::hit alone, and the
// accelerator's any hit (an occlusion query), which must be blocked exactly where Tri_Mesh::hit hits.
Stress_Count compare(const std::vector<Triangle>& tris, const std::function<Ray(RNG&)>& make_ray, int rays,
                     uint64_t seed) {
	Tri_Mesh mesh(std::vector<Triangle>(tris), 4);
	RNG rng(seed);
	Stress_Count count;
	auto show = [](const Trace& t) { return t.hit ? "hits at t = " + std::to_string(t.distance) : std::string("misses"); };
	for (int i = 0; i < rays; i++) {
		Ray ray = make_ray(rng);
		Trace expected = brute_force(tris, ray), got = mesh.hit(ray), alone = mesh.bvh.hit(ray);
		bool blocked = mesh.accelerator.occluded(mesh.bvh, ray);
		auto differs = [&](const Trace& t) { return !same(t, expected) && !same(t, brute_force_in_boxes(tris, ray)); };
		count.add(differs(got) || differs(alone) || blocked != got.hit, [&] {
			return stress::show(ray) + ": brute force " + show(expected) + ", Tri_Mesh::hit " + show(got) +
			       ", BVH::hit " + show(alone) + ", Accelerator::occluded " + (blocked ? "blocked" : "not blocked");
		});
	}
	return count;
}

void require_agreement(const Stress_Count& count, const char* scene) {
	INFO("BVH::hit on " << scene << ": " << count.report("rays differ from brute force") << ".\n"
	     << "Check BBox::hit for 1/0 = inf and 0 * inf = NaN (compare so that NaN keeps the box), inclusive "
	        "bounds, and that the traversal never drops a child whose box the ray only touches (handout §3.3).");
	CHECK(count.failures == 0);
	std::printf("stress count: BVH vs brute force on %s: %zu of %zu differ\n", scene, count.failures, count.inputs);
}

// A direction along an axis (sign random), or in a coordinate plane, or any.
Vec3 axis_direction(RNG& rng) {
	Vec3 d{0.0f};
	int axis = int(rng.integer(3));
	d[axis] = rng.coin_flip(0.5f) ? 1.0f : -1.0f;
	if (rng.coin_flip(0.5f)) d[(axis + 1) % 3] = rng.unit() - 0.5f; // in a coordinate plane
	return d;
}

// Axis-aligned unit cubes at integer positions of a 4 x 4 x 4 grid, every other one present: many
// node boxes share faces at integer coordinates.
std::vector<Triangle> cube_grid() {
	std::vector<Triangle> tris;
	for (int x = 0; x < 4; x++)
		for (int y = 0; y < 4; y++)
			for (int z = 0; z < 4; z++)
				if ((x + y + z) % 2 == 0) {
					auto c = cube(1.0f, Vec3{float(x), float(y), float(z)});
					tris.insert(tris.end(), c.begin(), c.end());
				}
	return tris;
}

// A 20 x 20 grid of quads in the plane z = 1.5 and another in x = 2: flat node boxes.
std::vector<Triangle> planar_walls() {
	std::vector<Triangle> tris;
	for (int i = 0; i < 20; i++)
		for (int j = 0; j < 20; j++) {
			float x0 = 0.2f * i, y0 = 0.2f * j, x1 = x0 + 0.2f, y1 = y0 + 0.2f;
			tris.push_back(flat_triangle(Vec3{x0, y0, 1.5f}, Vec3{x1, y0, 1.5f}, Vec3{x1, y1, 1.5f}));
			tris.push_back(flat_triangle(Vec3{x0, y0, 1.5f}, Vec3{x1, y1, 1.5f}, Vec3{x0, y1, 1.5f}));
			tris.push_back(flat_triangle(Vec3{2.0f, x0, y0}, Vec3{2.0f, x1, y0}, Vec3{2.0f, x1, y1}));
			tris.push_back(flat_triangle(Vec3{2.0f, x0, y0}, Vec3{2.0f, x1, y1}, Vec3{2.0f, x0, y1}));
		}
	return tris;
}

// A point in [0, 4]^3 with coordinates on the quarter grid, so often exactly on a box face.
Vec3 grid_point(RNG& rng) {
	return Vec3{0.25f * float(rng.integer(17)), 0.25f * float(rng.integer(17)), 0.25f * float(rng.integer(17))};
}

} // namespace

TEST_CASE("Stress: BVH equals brute force for axis-aligned rays and rays in coordinate planes", "[stress][task3]") {
	auto tris = cube_grid();
	auto ray = [](RNG& rng) { return Ray(Vec3{4.0f * rng.unit(), 4.0f * rng.unit(), 4.0f * rng.unit()}, axis_direction(rng)); };
	require_agreement(compare(tris, ray, 20000, 1), "a grid of cubes, axis-aligned rays");
}

TEST_CASE("Stress: BVH equals brute force for rays starting exactly on box faces", "[stress][task3]") {
	auto tris = cube_grid();
	auto ray = [](RNG& rng) {
		Vec3 dir = rng.coin_flip(0.5f) ? axis_direction(rng) : random_unit(rng);
		return Ray(grid_point(rng), dir);
	};
	require_agreement(compare(tris, ray, 20000, 2), "a grid of cubes, rays from face points");
}

TEST_CASE("Stress: BVH equals brute force on planar walls (flat boxes), also for rays in their planes",
          "[stress][task3]") {
	auto tris = planar_walls();
	auto ray = [](RNG& rng) {
		Vec3 origin = grid_point(rng);
		if (rng.coin_flip(0.25f)) origin.z = 1.5f; // in the plane of a wall
		Vec3 dir = rng.coin_flip(0.5f) ? axis_direction(rng) : random_unit(rng);
		return Ray(origin - 0.5f * Vec3{1.0f}, dir);
	};
	require_agreement(compare(tris, ray, 20000, 3), "planar walls");
}

TEST_CASE("Stress: BVH equals brute force on triangles with coincident centroids", "[stress][task3]") {
	// 1000 triangles of random shape and size, each moved so that its centroid is exactly c... as
	// nearly as float allows; then many centroids coincide bit for bit.
	RNG rng(4);
	std::vector<Triangle> tris;
	Vec3 c{0.5f, 0.25f, -0.75f};
	for (int i = 0; i < 1000; i++) {
		float size = 0.01f + rng.unit();
		Vec3 a = size * random_unit(rng), b = size * random_unit(rng);
		Vec3 d = -(a + b); // a + b + d = 0: the centroid of (a, b, d) is 0
		tris.push_back(flat_triangle(c + a, c + b, c + d));
	}
	auto ray = [c](RNG& rng) {
		Vec3 w = random_unit(rng);
		return Ray(c + 3.0f * w, -w + 0.3f * random_unit(rng));
	};
	require_agreement(compare(tris, ray, 5000, 5), "triangles around one centroid");
}

TEST_CASE("Stress: a BVH over 10^6 identical triangles builds and hits like one triangle", "[stress][task3]") {
	Triangle one = flat_triangle(Vec3{-1.0f, -1.0f, 0.5f}, Vec3{1.0f, -1.0f, 0.5f}, Vec3{0.0f, 1.0f, 0.5f});
	std::vector<Triangle> tris(1000000, one);
	Tri_Mesh mesh(std::move(tris), 4);
	RNG rng(6);
	Stress_Count count;
	for (int i = 0; i < 200; i++) {
		Vec3 w = random_unit(rng);
		Ray ray(Vec3{0.0f, 0.0f, 0.5f} + 3.0f * w, -w + 0.5f * random_unit(rng));
		Trace expected = one.hit(ray), got = mesh.hit(ray), alone = mesh.bvh.hit(ray);
		auto differs = [&](const Trace& t) { return t.hit != expected.hit || (t.hit && t.distance != expected.distance); };
		count.add(differs(got) || differs(alone), [&] { return stress::show(ray); });
	}
	require_agreement(count, "10^6 identical triangles");
}

TEST_CASE("Stress: BVH equals brute force on a tree dozens of levels deep", "[stress][task3]") {
	// 950 parallel triangles in the planes x = 1e-37 * 1.2^k, spread over float's whole range:
	// binned SAH splits off a dozen at a time, 66 levels deep, and a ray along the row overlaps the
	// boxes of everything ahead of it, so the closest-hit traversal keeps some 110 children waiting
	// (more than the 64 the fast accelerator's stack holds before it moves to the heap). The last
	// ten triangles face the other way (they cover y + z >= 1, the others y + z <= 1): a ray with
	// y + z > 1 passes by every triangle until them, so its hit is in a child that waited at the
	// bottom of the stack.
	std::vector<Triangle> tris;
	for (int k = 0; k < 950; k++) {
		float x = float(1e-37 * std::pow(1.2, k));
		if (k < 940) tris.push_back(flat_triangle(Vec3{x, -1.0f, -1.0f}, Vec3{x, 2.0f, -1.0f}, Vec3{x, -1.0f, 2.0f}));
		else tris.push_back(flat_triangle(Vec3{x, 2.0f, 2.0f}, Vec3{x, -1.0f, 2.0f}, Vec3{x, 2.0f, -1.0f}));
	}
	auto ray = [](RNG& rng) {
		float x = float(1e-37 * std::pow(1.2, 951.0 * rng.unit() - 1.0)); // somewhere along the row
		float offset = rng.coin_flip(0.5f) ? -0.5f : 1.0f; // y + z < 1 or y + z > 1
		Vec3 origin{x, offset + 0.5f * rng.unit(), offset + 0.5f * rng.unit()};
		return Ray(origin, Vec3{rng.coin_flip(0.5f) ? 1.0f : -1.0f, 0.0f, 0.0f});
	};
	require_agreement(compare(tris, ray, 2000, 7), "950 triangles in a row, a deep tree");
}

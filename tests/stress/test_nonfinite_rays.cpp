// Stress (handouts §2.3, §3.3): NaN or infinity anywhere in a ray, zero-length directions and
// zero-area triangles give "no hit", never a NaN distance or a crash, at every level: Triangle,
// Sphere, a mesh's BVH, and a whole scene (instances with transforms).
#include "scene.h"
#include "stress_show.h"
#include "stress_count.h"
#include "stress_meshes.h"

#include "lab_catch2.h"

#include <glm/gtc/matrix_transform.hpp>

#include <functional>
#include <limits>

namespace {

const float NAN_F = std::numeric_limits<float>::quiet_NaN();

// A ray that would hit everything below, with one of its 8 numbers replaced by `bad`.
Ray spoiled_ray(int component, float bad) {
	Ray ray(Vec3{0.1f, 0.2f, 5.0f}, Vec3{0.01f, -0.02f, -1.0f});
	if (component < 3) ray.point[component] = bad;
	else if (component < 6) ray.dir[component - 3] = bad;
	else ray.dist_bounds[component - 6] = bad;
	return ray;
}

// Every ray with a NaN, +inf or -inf in it, except dist_bounds.y = +inf (the usual "no limit") and
// dist_bounds.x = -inf (then the bounds are the whole line, a valid if unusual request).
std::vector<Ray> nonfinite_rays() {
	std::vector<Ray> rays;
	for (int c = 0; c < 8; c++) {
		for (float bad : {NAN_F, INF_F, -INF_F}) {
			if ((c == 7 && bad == INF_F) || (c == 6 && bad == -INF_F)) continue;
			rays.push_back(spoiled_ray(c, bad));
		}
	}
	// All components of the direction at once, and both bounds NaN.
	rays.push_back(Ray(Vec3{0.0f, 0.0f, 5.0f}, Vec3{NAN_F}));
	rays.push_back(Ray(Vec3{0.0f, 0.0f, 5.0f}, Vec3{INF_F, -INF_F, INF_F}));
	rays.push_back(Ray(Vec3{0.0f, 0.0f, 5.0f}, Vec3{0.0f, 0.0f, -1.0f}, Vec2{NAN_F}));
	return rays;
}

using Hit_Function = std::function<Trace(const Ray&)>;

// Counts the rays for which `hit` reports a hit.
void count_hits(const char* what, const Hit_Function& hit, const std::vector<Ray>& rays, Stress_Count& count) {
	for (const Ray& ray : rays) {
		Trace got = hit(ray);
		count.add(got.hit, [&] {
			return std::string(what) + " " + stress::show(ray) + " gave a hit at t = " + std::to_string(got.distance);
		});
	}
}

Scene scene_of_everything() {
	Scene scene;
	Material white;
	scene.materials.push_back(white);
	scene.material_names.push_back("white");
	Mat4 moved = glm::translate(Mat4(1.0f), Vec3{0.0f, 0.0f, -1.0f});
	scene.objects.emplace_back(Sphere{1.0f}, moved, 0u, 0u);
	scene.objects.emplace_back(Tri_Mesh(square(3.0f, Vec3{0.0f}), 4), Mat4(1.0f), 0u, 1u);
	scene.commit();
	return scene;
}

} // namespace

TEST_CASE("Stress: a NaN or infinity in a ray's origin, direction or bounds gives no hit at every level",
          "[stress][task2][task3]") {
	std::vector<Ray> rays = nonfinite_rays();
	// Sanity: the same ray without the bad number hits each of them.
	Triangle tri = flat_triangle(Vec3{-3, -3, 0}, Vec3{3, -3, 0}, Vec3{0, 3, 0});
	Sphere sphere{1.0f};
	Tri_Mesh mesh(icosphere(1, Vec3{0.0f}), 4);
	Scene scene = scene_of_everything();
	Ray good(Vec3{0.1f, 0.2f, 5.0f}, Vec3{0.01f, -0.02f, -1.0f});
	REQUIRE(tri.hit(good).hit);
	REQUIRE(sphere.hit(good).hit);
	REQUIRE(mesh.hit(good).hit);
	REQUIRE(scene.hit(good).hit);

	Stress_Count count;
	count_hits("Triangle::hit", [&](const Ray& r) { return tri.hit(r); }, rays, count);
	count_hits("Sphere::hit", [&](const Ray& r) { return sphere.hit(r); }, rays, count);
	count_hits("Tri_Mesh::hit (BVH)", [&](const Ray& r) { return mesh.hit(r); }, rays, count);
	count_hits("Scene::hit", [&](const Ray& r) { return scene.hit(r); }, rays, count);
	INFO(count.report("non-finite rays reported a hit") << ".\n"
	     << "Write every acceptance test positively (t >= t_min && t <= t_max, u >= 0 ...): any comparison with "
	        "NaN is false, so NaN then falls out as a miss (handout §2.3).");
	CHECK(count.failures == 0);
	std::printf("stress count: non-finite rays with a hit %zu of %zu\n", count.failures, count.inputs);
}

TEST_CASE("Stress: zero-length directions give no hit at every level", "[stress][task2][task3]") {
	Triangle tri = flat_triangle(Vec3{-3, -3, 0}, Vec3{3, -3, 0}, Vec3{0, 3, 0});
	Sphere sphere{1.0f};
	Tri_Mesh mesh(icosphere(1, Vec3{0.0f}), 4);
	Scene scene = scene_of_everything();
	// From outside, from inside the sphere, and from a point on the triangle.
	std::vector<Ray> rays;
	for (Vec3 origin : {Vec3{0.1f, 0.2f, 5.0f}, Vec3{0.1f, 0.2f, 0.3f}, Vec3{0.0f, 0.0f, 0.0f}, Vec3{0.5f, 0.0f, 0.0f}})
		rays.push_back(Ray(origin, Vec3{0.0f}));
	Stress_Count count;
	count_hits("Triangle::hit", [&](const Ray& r) { return tri.hit(r); }, rays, count);
	count_hits("Sphere::hit", [&](const Ray& r) { return sphere.hit(r); }, rays, count);
	count_hits("Tri_Mesh::hit (BVH)", [&](const Ray& r) { return mesh.hit(r); }, rays, count);
	count_hits("Scene::hit", [&](const Ray& r) { return scene.hit(r); }, rays, count);
	INFO(count.report("rays with a zero direction reported a hit") << ".\n"
	     << "A zero direction makes det = 0 for a triangle and a = 0 for a sphere: return a miss, not a division "
	        "by zero (handouts §2.1, §2.2).");
	CHECK(count.failures == 0);
	std::printf("stress count: zero-direction rays with a hit %zu of %zu\n", count.failures, count.inputs);
}

TEST_CASE("Stress: zero-area triangles are never hit, alone or inside a mesh's BVH", "[stress][task2][task3]") {
	RNG rng(5);
	Stress_Count count;
	std::vector<Triangle> degenerate;
	for (int i = 0; i < 200; i++) {
		Vec3 a = random_unit(rng), b = random_unit(rng);
		// Collinear along an axis: the other two coordinates are equal, so e1 x e2 is exactly 0.
		Vec3 c = a, d = a;
		int axis = int(rng.integer(3));
		c[axis] += 0.5f;
		d[axis] -= 0.25f;
		degenerate.push_back(flat_triangle(a, a, a)); // a point
		degenerate.push_back(flat_triangle(a, c, d)); // a segment
		degenerate.push_back(flat_triangle(a, b, b)); // two vertices equal
	}
	Tri_Mesh mesh(std::vector<Triangle>(degenerate), 4);
	for (const Triangle& tri : degenerate) {
		// Rays through each vertex and through the middle of the segment, from random directions.
		for (Vec3 target : {tri.v0.position, tri.v1.position, 0.5f * (tri.v0.position + tri.v2.position)}) {
			Vec3 w = random_unit(rng);
			Ray ray(target + 2.0f * w, -w);
			Trace alone = tri.hit(ray), in_mesh = mesh.hit(ray);
			count.add(alone.hit || in_mesh.hit, [&] {
				return stress::show(ray) + " hit the zero-area triangle " + stress::show(tri.v0.position) +
				       ", " + stress::show(tri.v1.position) + ", " + stress::show(tri.v2.position);
			});
		}
	}
	INFO(count.report("rays hit a zero-area triangle") << ".\n"
	     << "A zero-area triangle has n = e1 x e2 = 0, so det = 0: return a miss (handout §2.1).");
	CHECK(count.failures == 0);
	std::printf("stress count: zero-area triangle hits %zu of %zu\n", count.failures, count.inputs);
}

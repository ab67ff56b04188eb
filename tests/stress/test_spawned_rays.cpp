// Stress (handout §4.5): rays spawned at a hit point (reflection, refraction, and light-sampled
// "shadow" directions) never hit the surface they leave, however far the scene is from the origin.
//
// The scene: a floor (the material under test) closing the bottom of a tilted box of size 10 whose five
// other faces emit towards the inside. A camera ray hits the floor; with max_depth = 1 the path
// tracer spawns at most one ray from there, which a Lifecycle_Recorder records with its hit. The
// floor is flat, so a spawned ray that hits it has hit the surface it leaves: a self-intersection.
// Measured with variants of the reference: new rays from the hit point with a fixed
// dist_bounds.x = 1e-4 hit the Lambertian floor again 10 times in 10^4 at offset 10^2 and 3589 times
// at 10^4 (the mirror and the glass floor: 2757 and 2235 times at 10^4); raising dist_bounds.x to
// spawn_ray's offset (1 + max |p_i|) * k * 2^-24 instead still lets 46 of the 4 * 10^4 rays from the
// Lambertian floor (grazing directions) hit it again. Moving the origin that far off the surface,
// along the normal, as spawn_ray does (spawn_ray.h), gives none with k = 8 or spawn_ray's k (k = 4:
// 83, k = 2: 1497 on the Lambertian floor; handout §4.2, §4.5).
#include "furnace_scenes.h"
#include "lifecycle.h"
#include "pathtracer.h"
#include "rng.h"
#include "stress_show.h"
#include "stress_count.h"
#include "stress_meshes.h"

#include "lab_catch2.h"

#include <glm/gtc/matrix_transform.hpp>

namespace {

constexpr float BOX = 10.0f;
constexpr uint32_t FLOOR_OBJECT = 1; // the floor's object index in the scene
const Vec3 OFFSET_DIRECTION = glm::normalize(Vec3{0.6f, -0.48f, 0.64f});

// Box coordinates to world: tilted (an axis-aligned floor would make rounding errors lie in its
// plane and hide them), then moved to `corner`.
struct Placement {
	Vec3 corner;
	Mat3 rotation = Mat3(glm::rotate(Mat4(1.0f), 0.7f, glm::normalize(Vec3{1.0f, 2.0f, 0.5f})));

	Vec3 operator()(Vec3 p) const {
		return corner + rotation * p;
	}
};

// The box [0, BOX]^3 placed by `place`, normals turned inwards; triangles 0 and 1 are the floor z = 0.
Scene floor_in_emitting_box(const Material& floor, const Placement& place, bool environment) {
	std::vector<Triangle> box = cube(BOX, Vec3{0.0f});
	for (Triangle& tri : box) {
		tri = flat_triangle(place(tri.v0.position), place(tri.v1.position), place(tri.v2.position));
		Vec3 n = -tri.v0.normal;
		tri.v0.normal = tri.v1.normal = tri.v2.normal = n;
	}
	std::vector<Triangle> floor_tris(box.begin(), box.begin() + 2), walls(box.begin() + 2, box.end());
	Scene scene;
	scene.materials = {diffuse_material(Spectrum{0.0f}, Spectrum{1.0f}), floor};
	scene.material_names = {"emitting walls", "floor"};
	scene.objects.emplace_back(Tri_Mesh(std::move(walls), 4), Mat4(1.0f), 0u, 0u);
	scene.objects.emplace_back(Tri_Mesh(std::move(floor_tris), 4), Mat4(1.0f), 1u, FLOOR_OBJECT);
	if (environment) scene.environment = Env_Constant{Spectrum{1.0f}};
	scene.commit();
	return scene;
}

// Camera-like rays from above the middle of the box to points of the floor at least 2 from the
// walls (so that a spawned ray's first hit is at least 2 away, beyond any sane offset).
struct Spawned_Rays {
	Stress_Count self_intersections; // inputs: camera rays; failures: a spawned ray hit the floor
	size_t spawned = 0;              // camera rays from whose hit a ray was spawned
};

Spawned_Rays count_self_intersections(const Material& floor, bool environment, int rays_per_offset, uint64_t seed) {
	Spawned_Rays count;
	RNG rng(seed);
	for (float offset : {1.0f, 1e2f, 1e3f, 1e4f}) {
		Placement place{offset * OFFSET_DIRECTION};
		Scene scene = floor_in_emitting_box(floor, place, environment);
		Render_Settings settings;
		settings.max_depth = 1;
		Pathtracer pathtracer(scene, settings);
		Vec3 eye = place(Vec3{0.5f * BOX, 0.5f * BOX, 0.8f * BOX});
		for (int i = 0; i < rays_per_offset; i++) {
			Vec3 target = place(Vec3{2.0f + 6.0f * rng.unit(), 2.0f + 6.0f * rng.unit(), 0.0f});
			Ray ray(eye, glm::normalize(target - eye));
			Lifecycle_Recorder recorder;
			pathtracer.trace(rng, ray);
			const auto& spawned_rays = recorder.rays().at(0)->children;
			bool hit_floor_again = false;
			for (const auto& spawned : spawned_rays) {
				hit_floor_again |= spawned->hit.hit && spawned->hit.object == FLOOR_OBJECT;
			}
			count.spawned += !spawned_rays.empty();
			count.self_intersections.add(hit_floor_again, [&] {
				return "offset " + std::to_string(offset) + ", camera ray " + stress::show(ray);
			});
		}
	}
	return count;
}

void require_none(const Spawned_Rays& rays, const char* what) {
	const Stress_Count& count = rays.self_intersections;
	{
		// Only a spawned ray can hit the floor again: the test needs the path tracer to spawn them. (A
		// light sample below the horizon of a point lifted off the floor weighs 0 and spawns none.)
		INFO("Pathtracer::shade spawned a ray from only " << rays.spawned << " of " << count.inputs
		                                                  << " hits on " << what << " with max_depth = 1 (handout §4.2)");
		CHECK(rays.spawned > count.inputs / 2);
	}
	INFO("Pathtracer::shade: " << count.report(std::string("rays spawned by ") + what +
	                                          " from a floor at offsets 1 ... 10^4 hit the floor again")
	                           << ".\nThe new ray must start beyond the rounding error of the hit point, which "
	                              "grows with its coordinates: move its origin off the surface, along the normal to "
	                              "the side it leaves on, by (1 + max |p_i|) * k * 2^-24 with k of at least 8 (the "
	                              "reference: 64), and keep dist_bounds = {0, inf}. A fixed offset such as 1e-4 fails "
	                              "far from the origin, and raising dist_bounds.x by the growing offset instead of "
	                              "moving the origin still lets grazing directions hit the surface again (handout "
	                              "§4.2).");
	CHECK(count.failures == 0);
	std::printf("stress count: self-intersections of %s: %zu of %zu (rays spawned: %zu)\n", what, count.failures,
	            count.inputs, rays.spawned);
}

} // namespace

TEST_CASE("Stress: diffuse bounces and light-sampled (shadow) rays never hit the surface they leave, offsets 1 ... 10^4",
          "[stress][task4]") {
	require_none(count_self_intersections(diffuse_material(Spectrum{0.5f}, Spectrum{0.0f}), false, 10000, 11),
	             "a Lambertian floor (BSDF and light samples)");
}

TEST_CASE("Stress: reflected rays never hit the mirror they leave, offsets 1 ... 10^4", "[stress][task4]") {
	require_none(count_self_intersections(mirror_material(Spectrum{1.0f}), false, 10000, 12), "a mirror floor");
}

TEST_CASE("Stress: reflected and refracted rays never hit the glass they leave, offsets 1 ... 10^4", "[stress][task4]") {
	require_none(count_self_intersections(glass_material(Spectrum{1.0f}, Spectrum{1.0f}, 1.5f), true, 10000, 13),
	             "a glass floor (reflection and refraction)");
}

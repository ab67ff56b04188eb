// What a scene does not need, the renderer does not do: no hierarchy over a handful of objects,
// no light sampling where it cannot help, no sampling table for an environment that is not
// importance-sampled, and an any-hit query that stops at the first hit. Each is shown by a
// counter, with a case where the work is done so that the counter is seen to count.
#include "call_counter.h"
#include "furnace_scenes.h"
#include "light_scenes.h"
#include "render.h"
#include "scene_loader.h"
#include "test_materials.h"

#include "lab_catch2.h"
#include <glm/gtc/matrix_transform.hpp>

#include <random>

namespace {

struct Counts {
	uint64_t closest_hits, light_samples, light_pdfs;
};

// The closest-hit queries and light-sampling calls made while rendering `scene` (64 x 64, 4 spp,
// one thread).
Counts count_render(const Scene& scene) {
	Render_Settings settings;
	settings.width = settings.height = 64;
	settings.samples = 4;
	Render_Options options;
	options.threads = 1; // render() then works on this thread, where the counter is active
	Call_Counter counter;
	render(Pathtracer(scene, settings), options);
	return Counts{counter.closest_hits, counter.light_samples, counter.light_pdfs};
}

// A sphere of `material` under a square light, seen from outside.
Scene sphere_under_light(const Material& material) {
	Furnace_Options options;
	options.has_environment = false;
	Scene scene = sphere_seen_from_outside(material, options, 4.0f, 40.0f);
	scene.objects = std::move(scene.bvh.primitives); // reopen the committed scene
	add_object(scene, ceiling_square(0.5f, 2.0f), add_material(scene, emitter(Spectrum{4.0f}), "light"));
	scene.commit();
	return scene;
}

} // namespace

TEST_CASE("a scene of a handful of objects is traced without a hierarchy", "[framework][skip]") {
	for (const char* file : {"scenes/furnace.json", "scenes/bunny.json", "scenes/dragon.json"}) {
		Scene scene = load_scene(file);
		INFO(file << ": " << scene.bvh.primitives.size() << " objects, " << scene.bvh.nodes.size()
		          << " top-level nodes; at most Scene::HANDFUL_OF_OBJECTS objects must share one leaf");
		CHECK(scene.bvh.primitives.size() <= Scene::HANDFUL_OF_OBJECTS);
		CHECK(scene.bvh.nodes.size() == 1);
	}
	Scene cornell = load_scene("scenes/cornell_box.json");
	INFO("scenes/cornell_box.json: " << cornell.bvh.primitives.size() << " objects get a hierarchy");
	CHECK(cornell.bvh.nodes.size() > 1);
}

TEST_CASE("objects without a transform of their own share one BVH, and their hits are the objects' own",
          "[framework][skip]") {
	// (framework_tests links the reference tasks, so the scene's queries go through the fast
	// accelerator, accel/fast/flat_meshes.cpp; BVH::hit over the objects is the lab's two levels.)
	std::mt19937 random(11);
	std::uniform_real_distribution<float> unit(0.0f, 1.0f);
	for (const char* file : {"scenes/cornell_box.json", "scenes/cornell_spheres.json"}) {
		Scene scene = load_scene(file);
		BBox box = scene.bvh.bbox();
		size_t spheres = 0, hits = 0;
		for (const Instance& object : scene.bvh.primitives) spheres += std::holds_alternative<Sphere>(object.shape);
		for (int i = 0; i < 20000; i++) {
			Vec3 from = box.min + Vec3{unit(random), unit(random), unit(random)} * (box.max - box.min);
			Vec3 dir = glm::normalize(Vec3{unit(random), unit(random), unit(random)} - 0.5f);
			Ray ray(from, dir);
			Call_Counter calls;
			Trace flat = scene.hit(ray);
			INFO(file << ", ray " << i << ": every untransformed mesh is in one BVH, so Instance::hit runs only for "
			          << spheres << " spheres");
			REQUIRE(calls.instance_tests <= spheres);
			Trace two_levels = scene.bvh.hit(ray);
			REQUIRE(flat.hit == two_levels.hit);
			if (!flat.hit) continue;
			hits++;
			CHECK(flat.distance == two_levels.distance);
			CHECK(flat.object == two_levels.object);
			CHECK(flat.material == two_levels.material);
			CHECK(flat.normal == two_levels.normal);
			CHECK(flat.position == two_levels.position);
			CHECK(scene.occluded(ray) == true);
		}
		CHECK(hits > 10000);
	}
}

TEST_CASE("paths at mirrors and glass, and scenes without lights, sample no lights", "[framework][skip]") {
	// (The light is a black diffuse surface: paths end there, sampling nothing.)
	SECTION("a diffuse sphere under a light samples it (the counters count)") {
		Counts calls = count_render(sphere_under_light(diffuse_material(Spectrum{0.5f})));
		CHECK(calls.closest_hits > 0);
		CHECK(calls.light_samples > 0);
		CHECK(calls.light_pdfs > 0);
	}
	SECTION("a mirror or a glass sphere under a light: a discrete BSDF has no density to mix with a light's") {
		for (const Material& material :
		     {mirror_material(Spectrum{0.9f}), glass_material(Spectrum{1.0f}, Spectrum{1.0f}, 1.5f)}) {
			Counts calls = count_render(sphere_under_light(material));
			CHECK(calls.closest_hits > 0);
			CHECK(calls.light_samples == 0);
			CHECK(calls.light_pdfs == 0);
		}
	}
	SECTION("a diffuse sphere with neither emitters nor an environment") {
		Furnace_Options dark;
		dark.has_environment = false;
		Counts calls = count_render(sphere_seen_from_outside(diffuse_material(Spectrum{0.5f}), dark, 4.0f, 40.0f));
		CHECK(calls.closest_hits > 0);
		CHECK(calls.light_samples == 0);
		CHECK(calls.light_pdfs == 0);
	}
}

TEST_CASE("only an importance-sampled environment map builds a sampling table", "[framework][skip]") {
	Scene constant = load_scene("scenes/furnace.json");
	REQUIRE(constant.environment);
	INFO("scenes/furnace.json: a constant environment is an Env_Constant, a type without a table");
	CHECK(std::holds_alternative<Env_Constant>(*constant.environment));

	HDR_Image sky(8, 4, Spectrum{1.0f});
	Env_Map uniform(sky, false);
	CHECK(uniform.sampler.pdf_texel.empty());
	CHECK(uniform.sampler.cdf.empty());
	Env_Map importance(sky, true);
	CHECK(importance.sampler.pdf_texel.size() == 8 * 4);
	CHECK(importance.sampler.cdf.size() == 8 * 4);
}

TEST_CASE("the occlusion query agrees with the closest hit and stops at the first hit", "[framework][skip]") {
	SECTION("eight copies of one sphere on the ray: any hit tests one, closest hit all eight") {
		Scene scene;
		uint32_t white = add_material(scene, diffuse_material(Spectrum{0.5f}), "white");
		for (int i = 0; i < 8; i++) add_object(scene, Sphere{}, white); // unit spheres at the origin
		scene.commit();
		Ray ray(Vec3{-5.0f, 0.1f, 0.2f}, Vec3{1.0f, 0.0f, 0.0f});

		{
			Call_Counter calls;
			REQUIRE(scene.occluded(ray));
			CHECK(calls.instance_tests == 1);
		}
		Call_Counter calls;
		REQUIRE(scene.hit(ray).hit);
		CHECK(calls.instance_tests == 8);
	}
	SECTION("random segments through random triangles") {
		std::mt19937 random(7);
		std::uniform_real_distribution<float> coordinate(-1.0f, 1.0f), length(0.0f, 3.0f);
		auto point = [&] { return Vec3{coordinate(random), coordinate(random), coordinate(random)}; };
		std::vector<Triangle> triangles;
		for (int i = 0; i < 500; i++) {
			Vec3 centre = point(), normal = glm::normalize(point());
			triangles.push_back(Triangle{{centre, normal}, {centre + 0.4f * point(), normal}, {centre + 0.4f * point(), normal}});
		}
		Tri_Mesh mesh(std::move(triangles), 4);
		size_t blocked = 0;
		for (int i = 0; i < 20000; i++) {
			Ray ray(2.0f * point(), glm::normalize(point()), Vec2{0.0f, length(random)});
			bool closest = mesh.hit(ray).hit;
			blocked += closest;
			INFO("ray " << i);
			REQUIRE(mesh.accelerator.occluded(mesh.bvh, ray) == closest);
		}
		CHECK(blocked > 2000); // both answers are common
		CHECK(blocked < 18000);
	}
}

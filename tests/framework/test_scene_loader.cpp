// load_scene (framework/scene/scene_loader.h) and the scene format of scenes/README.md: the shipped
// scenes load as documented, every part of the format means what the README says, and every bad
// input is ONE Input_Error "<file>: <element>: <what was expected, and what was found>" — never a
// crash and never a silently ignored value.
#include "error.h"
#include "obj_loader.h"
#include "render.h"
#include "scene_loader.h"
#include "temp_dir.h"

#include "lab_catch2.h"

#include <algorithm>
#include <filesystem>

#include <algorithm>
#include <array>
#include <fstream>
#include <iterator>
#include <random>

namespace {

// --- Helpers

// The scene's objects in the order of the file (commit() moved them into the BVH, reordered).
std::vector<const Instance*> objects_in_file_order(const Scene& scene) {
	std::vector<const Instance*> objects;
	for (const Instance& instance : scene.bvh.primitives) objects.push_back(&instance);
	std::sort(objects.begin(), objects.end(), [](auto* a, auto* b) { return a->index < b->index; });
	return objects;
}

const Tri_Mesh& mesh_of(const Instance& instance) {
	REQUIRE(std::holds_alternative<Tri_Mesh>(instance.shape));
	return std::get<Tri_Mesh>(instance.shape);
}

size_t triangle_count(const Scene& scene) {
	size_t count = 0;
	for (const Instance& instance : scene.bvh.primitives) {
		if (std::holds_alternative<Tri_Mesh>(instance.shape)) count += mesh_of(instance).triangle_count();
	}
	return count;
}

const Material& material_named(const Scene& scene, const std::string& name) {
	auto it = std::find(scene.material_names.begin(), scene.material_names.end(), name);
	REQUIRE(it != scene.material_names.end());
	return scene.materials[size_t(it - scene.material_names.begin())];
}

void require_near(Vec3 actual, Vec3 expected, const std::string& what, float tolerance = 1e-5f) {
	INFO(what << ": expected (" << expected.x << ", " << expected.y << ", " << expected.z << "), got (" << actual.x
	          << ", " << actual.y << ", " << actual.z << ")");
	CHECK(glm::length(actual - expected) <= tolerance);
}

std::string write_file(const Temp_Dir& dir, const std::string& name, const std::string& text) {
	std::string path = dir.file(name);
	std::ofstream(path) << text;
	return path;
}

Scene load_text(const std::string& text) {
	Temp_Dir dir;
	return load_scene(write_file(dir, "scene.json", text));
}

// A small valid scene: a sphere and an inline triangle. Error tests change one piece of it.
const std::string BASE_SCENE = R"({
	"camera": {"position": [0, 1, 5], "target": [0, 1, 0], "up": [0, 1, 0], "vertical_fov": 45},
	"film": {"width": 32, "height": 16, "samples": 4, "max_depth": 5, "seed": 7},
	"materials": {
		"white": {"type": "lambertian", "albedo": [0.8, 0.8, 0.8]},
		"lamp": {"type": "emissive", "emission": [4, 4, 4]}
	},
	"objects": [
		{"type": "sphere", "material": "white", "radius": 1, "transform": [{"translate": [0, 1, 0]}]},
		{"type": "mesh", "material": "lamp", "vertices": [[0, 3, 0], [1, 3, 0], [0, 3, 1]], "triangles": [[0, 1, 2]]}
	]
})";

// BASE_SCENE with the one occurrence of `from` replaced by `to`.
std::string base_with(const std::string& from, const std::string& to) {
	size_t at = BASE_SCENE.find(from);
	REQUIRE(at != std::string::npos);
	REQUIRE(BASE_SCENE.find(from, at + 1) == std::string::npos);
	return BASE_SCENE.substr(0, at) + to + BASE_SCENE.substr(at + from.size());
}

// Loading `text` from a scene file must throw Input_Error("<file>: <element>: ...") whose message
// contains every string of `expected` (what was expected, and what was found).
void require_scene_error(const std::string& text, const std::string& element, std::vector<std::string> expected,
                         const Temp_Dir* dir_with_files = nullptr) {
	Temp_Dir own_dir;
	const Temp_Dir& dir = dir_with_files ? *dir_with_files : own_dir;
	std::string path = write_file(dir, "scene.json", text);
	CAPTURE(text);
	try {
		load_scene(path);
		FAIL("load_scene accepted a bad scene; expected an Input_Error at " << element);
	} catch (const Input_Error& e) {
		std::string message = e.what();
		CAPTURE(message);
		INFO("the message must start with \"<file>: <element>: \"");
		CHECK(message.rfind(path + ": " + element + ": ", 0) == 0);
		for (const std::string& part : expected) {
			INFO("the message must say: " << part);
			CHECK(message.find(part) != std::string::npos);
		}
	}
}

} // namespace

// --- The shipped scenes

TEST_CASE("cornell_box.json is the measured Cornell box: 8 objects, 32 triangles, the reference camera", "[scene]") {
	Scene scene = load_scene("scenes/cornell_box.json");
	CHECK(scene.path == "scenes/cornell_box.json");
	CHECK(scene.bvh.primitives.size() == 8);
	CHECK(triangle_count(scene) == 32);
	CHECK_FALSE(scene.environment.has_value());

	CHECK(scene.settings.width == 256);
	CHECK(scene.settings.height == 256);
	CHECK(scene.settings.samples == 64);
	CHECK(scene.settings.max_depth == 16);
	CHECK(scene.camera.v_fov == Approx(39.3077f));
	CHECK(scene.camera.aspect_ratio == 1.0f);
	INFO("camera at (278, 273, -800) looking along +z at (278, 273, 0), +y up (SOURCES.md)");
	require_near(Vec3(scene.camera.camera_to_world[3]), Vec3{278.0f, 273.0f, -800.0f}, "camera position");
	require_near(-Vec3(scene.camera.camera_to_world[2]), Vec3{0.0f, 0.0f, 1.0f}, "viewing direction");
	require_near(Vec3(scene.camera.camera_to_world[1]), Vec3{0.0f, 1.0f, 0.0f}, "camera up");

	CHECK(scene.material_names == std::vector<std::string>{"white", "red", "green", "light"});
	Material light = material_named(scene, "light"); // (a copy: GCC 14 suspects a reference to a temporary)
	CHECK(light.emission == Spectrum{15.0f});
	CHECK(light.bsdf.albedo() == Spectrum{0.0f});
	CHECK(material_named(scene, "white").bsdf.albedo() == Spectrum{0.73f});
	CHECK(material_named(scene, "red").bsdf.albedo() == Spectrum{0.65f, 0.05f, 0.05f});
	CHECK(material_named(scene, "green").bsdf.albedo() == Spectrum{0.12f, 0.45f, 0.15f});
	CHECK_FALSE(material_named(scene, "white").is_emissive());
}

TEST_CASE("cornell_box.json has exactly the triangles of cornell_box.obj, with the light facing down", "[scene]") {
	// The pbrt-v3 cross-check renders the OBJ; our JSON writes the same triangles inline: same
	// vertices, same split of each quad, same winding (so the one-sided light emits towards -y).
	using Corners = std::array<std::array<float, 3>, 3>;
	auto corners = [](const Triangle& t) {
		Corners c;
		for (int k = 0; k < 3; k++) {
			const Vec3& p = k == 0 ? t.v0.position : k == 1 ? t.v1.position : t.v2.position;
			c[k] = {p.x, p.y, p.z};
		}
		return c;
	};
	std::vector<Corners> ours, obj;
	Scene scene = load_scene("scenes/cornell_box.json");
	for (const Instance& instance : scene.bvh.primitives) {
		CHECK(instance.to_world == Mat4{1.0f});
		for (const Triangle& t : mesh_of(instance).bvh.primitives) ours.push_back(corners(t));
	}
	for (const Triangle& t : load_obj("scenes/meshes/cornell_box.obj")) obj.push_back(corners(t));
	std::sort(ours.begin(), ours.end());
	std::sort(obj.begin(), obj.end());
	REQUIRE(ours.size() == obj.size());
	for (size_t i = 0; i < ours.size(); i++) {
		for (int k = 0; k < 3; k++) {
			CAPTURE(i, k);
			// Both parse the same decimal numbers; allow a float rounding difference (1 um).
			require_near(Vec3{ours[i][k][0], ours[i][k][1], ours[i][k][2]}, Vec3{obj[i][k][0], obj[i][k][1], obj[i][k][2]},
			             "vertex of the JSON triangle vs the OBJ triangle", 1e-3f);
		}
	}
	for (const Instance& instance : scene.bvh.primitives) {
		if (scene.material_names[instance.material] != "light") continue;
		for (const Triangle& t : mesh_of(instance).bvh.primitives) {
			require_near(t.v0.normal, Vec3{0.0f, -1.0f, 0.0f}, "the light's normal (emission is towards the normal)");
		}
	}
}

TEST_CASE("cornell_spheres.json is the box without blocks, with two spheres", "[scene]") {
	Scene scene = load_scene("scenes/cornell_spheres.json");
	size_t spheres = 0;
	for (const Instance& instance : scene.bvh.primitives) spheres += std::holds_alternative<Sphere>(instance.shape);
	CHECK(spheres == 2);
	CHECK(scene.bvh.primitives.size() == 8); // 5 walls, the light, 2 spheres
	CHECK(triangle_count(scene) == 12);
	CHECK(material_named(scene, "light").emission == Spectrum{15.0f});
}

TEST_CASE("bunny.json and dragon.json load the Stanford meshes on a ground plane", "[scene]") {
	Scene bunny = load_scene("scenes/bunny.json");
	CHECK(bunny.bvh.primitives.size() == 2);
	CHECK(triangle_count(bunny) == 69451 + 2);
	CHECK(bunny.camera.aspect_ratio == Approx(float(bunny.settings.width) / float(bunny.settings.height)));

	Scene dragon = load_scene("scenes/dragon.json");
	CHECK(dragon.bvh.primitives.size() == 3);
	CHECK(triangle_count(dragon) == 202520 + 2 + 2);
	CHECK(material_named(dragon, "lamp").is_emissive());

	INFO("each model stands on the ground plane y = 0 and is in front of the camera");
	for (const Scene* scene : {&bunny, &dragon}) {
		const Instance& model = *objects_in_file_order(*scene)[0];
		CHECK(model.world_bbox.min.y == Approx(0.0f).margin(1e-3));
		Ray centre = scene->camera.generate_ray(Vec2{0.5f, 0.5f});
		Vec2 times = centre.dist_bounds;
		CHECK(model.world_bbox.hit(centre, times));
	}
}

TEST_CASE("furnace.json is a diffuse sphere of albedo 0.5 in a constant environment of radiance 1", "[scene]") {
	Scene scene = load_scene("scenes/furnace.json");
	REQUIRE(scene.bvh.primitives.size() == 1);
	CHECK(std::holds_alternative<Sphere>(scene.bvh.primitives[0].shape));
	CHECK(scene.materials[0].bsdf.albedo() == Spectrum{0.5f});
	REQUIRE(scene.environment.has_value());
	REQUIRE(std::holds_alternative<Env_Constant>(*scene.environment));
	CHECK(std::get<Env_Constant>(*scene.environment).radiance == Spectrum{1.0f});
	CHECK(scene.environment_radiance(Vec3{0.0f, 0.0f, 1.0f}) == Spectrum{1.0f});
}

TEST_CASE("Every shipped scene renders: a few samples of a small film are finite and not all black", "[scene]") {
	std::vector<std::string> paths;
	for (const auto& entry : std::filesystem::directory_iterator("scenes")) {
		if (entry.path().extension() == ".json") paths.push_back(entry.path().string());
	}
	std::sort(paths.begin(), paths.end());
	REQUIRE(paths.size() >= 12);
	for (const std::string& path : paths) {
		CAPTURE(path);
		Scene scene = load_scene(path);
		Render_Settings settings = scene.settings;
		settings.width = settings.height = 12;
		settings.samples = 2;
		settings.max_depth = 3;
		Film film = render(Pathtracer(scene, settings));
		CHECK(film.non_finite() == 0);
		float brightest = 0.0f;
		for (const Spectrum& pixel : film.mean().pixels) brightest = std::max(brightest, luminance(pixel));
		CHECK(brightest > 0.0f);
	}
}

// --- What the format means

TEST_CASE("Film settings are read, and default to Render_Settings when absent", "[scene]") {
	Scene scene = load_text(BASE_SCENE);
	CHECK(scene.settings.width == 32);
	CHECK(scene.settings.height == 16);
	CHECK(scene.settings.samples == 4);
	CHECK(scene.settings.max_depth == 5);
	CHECK(scene.settings.seed == 7);
	CHECK(scene.camera.aspect_ratio == 2.0f);

	Scene defaults = load_text(base_with(R"("film": {"width": 32, "height": 16, "samples": 4, "max_depth": 5, "seed": 7},)", ""));
	Render_Settings expected;
	CHECK(defaults.settings.width == expected.width);
	CHECK(defaults.settings.height == expected.height);
	CHECK(defaults.settings.samples == expected.samples);
	CHECK(defaults.settings.max_depth == expected.max_depth);
	CHECK(defaults.settings.seed == expected.seed);
}

TEST_CASE("The camera is Camera::look_at(position, target, up, vertical_fov, width / height); up defaults to +y", "[scene]") {
	Scene scene = load_text(base_with(R"("up": [0, 1, 0], )", ""));
	Camera expected = Camera::look_at(Vec3{0, 1, 5}, Vec3{0, 1, 0}, Vec3{0, 1, 0}, 45.0f, 2.0f);
	CHECK(scene.camera.camera_to_world == expected.camera_to_world);
	CHECK(scene.camera.v_fov == 45.0f);
	CHECK(scene.camera.aspect_ratio == 2.0f);
}

TEST_CASE("Materials are numbered in file order, with the documented defaults", "[scene]") {
	Scene scene = load_text(base_with(R"("lamp": {"type": "emissive", "emission": [4, 4, 4]})",
	                                  R"("lamp": {"type": "emissive", "emission": [4, 4, 4]},
		"mirror": {"type": "mirror"},
		"glass": {"type": "glass"},
		"tinted": {"type": "glass", "index_of_refraction": 1.33, "reflectance": [0.9, 0.9, 0.9], "transmittance": [0.5, 0.6, 0.7]},
		"glowing": {"type": "lambertian", "albedo": [0.1, 0.2, 0.3], "emission": [1, 2, 3]})"));
	REQUIRE(scene.material_names == std::vector<std::string>{"white", "lamp", "mirror", "glass", "tinted", "glowing"});

	const Material& lamp = scene.materials[1];
	INFO("\"emissive\" is a black Lambertian surface that emits");
	REQUIRE(std::holds_alternative<BSDF_Lambertian>(lamp.bsdf.bsdf));
	CHECK(lamp.bsdf.albedo() == Spectrum{0.0f});
	CHECK(lamp.emission == Spectrum{4.0f});

	REQUIRE(std::holds_alternative<BSDF_Mirror>(scene.materials[2].bsdf.bsdf));
	CHECK(std::get<BSDF_Mirror>(scene.materials[2].bsdf.bsdf).reflectance == Spectrum{1.0f});

	REQUIRE(std::holds_alternative<BSDF_Glass>(scene.materials[3].bsdf.bsdf));
	const BSDF_Glass& glass = std::get<BSDF_Glass>(scene.materials[3].bsdf.bsdf);
	CHECK(glass.index_of_refraction == 1.5f);
	CHECK(glass.reflectance == Spectrum{1.0f});
	CHECK(glass.transmittance == Spectrum{1.0f});

	const BSDF_Glass& tinted = std::get<BSDF_Glass>(scene.materials[4].bsdf.bsdf);
	CHECK(tinted.index_of_refraction == 1.33f);
	CHECK(tinted.reflectance == Spectrum{0.9f});
	CHECK(tinted.transmittance == Spectrum{0.5f, 0.6f, 0.7f});

	INFO("any material may also emit");
	CHECK(scene.materials[5].bsdf.albedo() == Spectrum{0.1f, 0.2f, 0.3f});
	CHECK(scene.materials[5].emission == Spectrum{1.0f, 2.0f, 3.0f});
	CHECK(scene.materials[0].emission == Spectrum{0.0f});
}

TEST_CASE("Objects keep their file position as index and refer to their material by name", "[scene]") {
	Scene scene = load_text(base_with(R"("triangles": [[0, 1, 2]]})", R"("triangles": [[0, 1, 2]]},
		{"type": "sphere", "material": "white", "radius": 2})"));
	auto objects = objects_in_file_order(scene);
	REQUIRE(objects.size() == 3);
	for (uint32_t i = 0; i < 3; i++) CHECK(objects[i]->index == i);
	CHECK(objects[0]->material == 0); // "white"
	CHECK(objects[1]->material == 1); // "lamp"
	CHECK(objects[2]->material == 0); // "white" again
	CHECK(std::get<Sphere>(objects[0]->shape).radius == 1.0f);
	CHECK(mesh_of(*objects[1]).triangle_count() == 1);
	CHECK(std::get<Sphere>(objects[2]->shape).radius == 2.0f);
}

TEST_CASE("Transform steps apply in order, the first step first", "[scene]") {
	auto sphere_with = [](const std::string& transform) {
		Scene scene = load_text(base_with(R"("transform": [{"translate": [0, 1, 0]}])", R"("transform": )" + transform));
		return *objects_in_file_order(scene)[0];
	};
	SECTION("translate then scale moves the centre by the scaled offset") {
		Instance sphere = sphere_with(R"([{"translate": [1, 0, 0]}, {"scale": 2}])");
		require_near(transform_point(sphere.to_world, Vec3{0.0f}), Vec3{2.0f, 0.0f, 0.0f}, "centre");
		require_near(sphere.world_bbox.max, Vec3{4.0f, 2.0f, 2.0f}, "bbox max");
	}
	SECTION("scale then translate does not scale the offset") {
		Instance sphere = sphere_with(R"([{"scale": 2}, {"translate": [1, 0, 0]}])");
		require_near(transform_point(sphere.to_world, Vec3{0.0f}), Vec3{1.0f, 0.0f, 0.0f}, "centre");
	}
	SECTION("scale by three factors") {
		Instance sphere = sphere_with(R"([{"scale": [1, 2, 3]}])");
		require_near(transform_point(sphere.to_world, Vec3{1.0f}), Vec3{1.0f, 2.0f, 3.0f}, "scaled point");
	}
	SECTION("rotate follows the right-hand rule: +x turns to +y about +z") {
		Instance sphere = sphere_with(R"([{"rotate": {"axis": [0, 0, 2], "degrees": 90}}])");
		require_near(transform_point(sphere.to_world, Vec3{1.0f, 0.0f, 0.0f}), Vec3{0.0f, 1.0f, 0.0f}, "rotated +x");
	}
	SECTION("a matrix is written row by row") {
		Instance sphere = sphere_with(R"([{"matrix": [[1, 0, 0, 5], [0, 1, 0, 6], [0, 0, 1, 7], [0, 0, 0, 1]]}])");
		require_near(transform_point(sphere.to_world, Vec3{0.0f}), Vec3{5.0f, 6.0f, 7.0f}, "translation column");
	}
	SECTION("no transform is the identity") {
		Scene scene = load_text(base_with(R"(, "transform": [{"translate": [0, 1, 0]}])", ""));
		CHECK(objects_in_file_order(scene)[0]->to_world == Mat4{1.0f});
	}
}

TEST_CASE("Inline meshes: given normals are normalized, missing ones are area-weighted, flat_shading uses face normals", "[scene]") {
	// The same fold as in test_obj_loader: face A (normal +y, area 2) and face B (normal +x, area 1).
	const std::string fold = R"("vertices": [[0, 0, 0], [0, 0, 2], [2, 0, 0], [0, 1, 0]], "triangles": [[0, 1, 2], [0, 3, 1]])";
	auto mesh_with = [&](const std::string& extra) {
		Scene scene = load_text(base_with(R"("vertices": [[0, 3, 0], [1, 3, 0], [0, 3, 1]], "triangles": [[0, 1, 2]])", fold + extra));
		std::vector<Triangle> triangles = mesh_of(*objects_in_file_order(scene)[1]).bvh.primitives;
		REQUIRE(triangles.size() == 2);
		// Face A is the one with vertex (2, 0, 0).
		if (triangles[0].v2.position != Vec3{2.0f, 0.0f, 0.0f}) std::swap(triangles[0], triangles[1]);
		return triangles;
	};
	SECTION("computed: shared vertices get normalize(2 (0,1,0) + 1 (1,0,0))") {
		std::vector<Triangle> t = mesh_with("");
		require_near(t[0].v0.normal, glm::normalize(Vec3{1.0f, 2.0f, 0.0f}), "shared vertex");
		require_near(t[0].v2.normal, Vec3{0.0f, 1.0f, 0.0f}, "vertex of face A only");
		require_near(t[1].v1.normal, Vec3{1.0f, 0.0f, 0.0f}, "vertex of face B only");
	}
	SECTION("given normals, one per vertex") {
		std::vector<Triangle> t = mesh_with(R"(, "normals": [[0, 0, 3], [0, 2, 0], [1, 0, 0], [0, 0, -1]])");
		require_near(t[0].v0.normal, Vec3{0.0f, 0.0f, 1.0f}, "normal [0, 0, 3] normalized");
		require_near(t[0].v1.normal, Vec3{0.0f, 1.0f, 0.0f}, "normal [0, 2, 0] normalized");
		require_near(t[1].v1.normal, Vec3{0.0f, 0.0f, -1.0f}, "normal of vertex 3");
	}
	SECTION("flat shading") {
		std::vector<Triangle> t = mesh_with(R"(, "flat_shading": true)");
		for (Vec3 n : {t[0].v0.normal, t[0].v1.normal, t[0].v2.normal}) require_near(n, Vec3{0.0f, 1.0f, 0.0f}, "face A");
		for (Vec3 n : {t[1].v0.normal, t[1].v1.normal, t[1].v2.normal}) require_near(n, Vec3{1.0f, 0.0f, 0.0f}, "face B");
	}
}

TEST_CASE("Mesh files are found relative to the scene file's folder, whatever the working directory", "[scene]") {
	Temp_Dir dir;
	std::filesystem::create_directories(dir.path() / "sub" / "meshes");
	write_file(dir, "sub/meshes/quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
	std::string scene_path = write_file(
		dir, "sub/scene.json", base_with(R"("vertices": [[0, 3, 0], [1, 3, 0], [0, 3, 1]], "triangles": [[0, 1, 2]])",
	                                     R"("file": "meshes/quad.obj")"));
	Scene scene = load_scene(scene_path); // the working directory is the repository root
	CHECK(triangle_count(scene) == 2);
}

TEST_CASE("A scene may have no objects (only an environment)", "[scene]") {
	Scene scene = load_text(R"({
		"camera": {"position": [0, 0, 0], "target": [0, 0, -1], "vertical_fov": 60},
		"materials": {},
		"objects": [],
		"environment": {"type": "constant", "radiance": [0.5, 0.25, 0]}
	})");
	CHECK(scene.bvh.primitives.empty());
	CHECK_FALSE(scene.hit(Ray(Vec3{0.0f}, Vec3{0.0f, 0.0f, -1.0f})).hit);
	CHECK(scene.environment_radiance(Vec3{0.0f, 1.0f, 0.0f}) == Spectrum{0.5f, 0.25f, 0.0f});
}

TEST_CASE("An image environment reads the map, multiplies it by scale, and builds the sampler only if asked", "[scene][image]") {
	Temp_Dir dir;
	std::filesystem::copy_file("scenes/hdri/potsdamer_platz_1k.hdr", dir.path() / "sky.hdr");
	auto load_env = [&](const std::string& settings) {
		Scene scene = load_scene(write_file(dir, "scene.json", base_with(R"("objects": [)", R"("environment": {"type": "image", "file": "sky.hdr")" + settings + R"(},
	"objects": [)")));
		REQUIRE(scene.environment.has_value());
		REQUIRE(std::holds_alternative<Env_Map>(*scene.environment));
		return std::get<Env_Map>(*scene.environment);
	};
	Env_Map plain = load_env("");
	CHECK(plain.image.w == 1024);
	CHECK(plain.image.h == 512);
	CHECK(plain.importance_sampling);
	CHECK(plain.sampler.pdf_texel.size() == size_t(1024) * 512);

	Env_Map scaled = load_env(R"(, "scale": 2, "importance_sampling": false)");
	CHECK_FALSE(scaled.importance_sampling);
	CHECK(scaled.sampler.pdf_texel.empty());
	for (size_t i : {size_t(0), size_t(12345), plain.image.pixels.size() - 1}) {
		CAPTURE(i);
		CHECK(scaled.image.pixels[i] == 2.0f * plain.image.pixels[i]);
	}
}

TEST_CASE("The complete example in scenes/README.md is a valid scene", "[scene][image]") {
	std::ifstream file("scenes/README.md");
	std::string readme{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
	size_t start = readme.find("```json\n");
	REQUIRE(start != std::string::npos);
	start += 8;
	std::string example = readme.substr(start, readme.find("```", start) - start);
	// Its file names are relative to scenes/; the copy lives elsewhere, so make them absolute.
	std::string scenes = std::filesystem::absolute("scenes").string() + "/";
	for (size_t at = 0; (at = example.find("\"file\": \"", at)) != std::string::npos; at += 9) example.insert(at + 9, scenes);
	Scene scene = load_text(example);
	CHECK(scene.material_names == std::vector<std::string>{"floor", "clay", "chrome", "glass", "lamp"});
	CHECK(scene.bvh.primitives.size() == 5);
	CHECK(triangle_count(scene) == 2 + 3674 + 2);
	REQUIRE(scene.environment.has_value());
	CHECK(std::holds_alternative<Env_Map>(*scene.environment));
}

// --- Errors: one Input_Error "<file>: <element>: <expected, found>" for every bad input

TEST_CASE("Malformed JSON is reported with its line and column", "[scene][errors]") {
	// Line 2 misses the comma after "target": the parser stops at the end of the unexpected
	// string "up" (columns 56 to 59; the tab counts as one column).
	std::string text = "{\n\t\"camera\": {\"position\": [0, 1, 5], \"target\": [0, 1, 0] \"up\": [0, 1, 0]},\n}";
	require_scene_error(text, "line 2, column 59", {"not valid JSON", "expected"});
	require_scene_error("", "line 1, column 1", {"not valid JSON", "unexpected end of input"});
	require_scene_error("{\"camera\": tru}", "line 1, column 15", {"not valid JSON"});
	INFO("NaN and Infinity are not JSON: the parser stops at their first letter (line 9, column 53)");
	require_scene_error(base_with("\"radius\": 1", "\"radius\": NaN"), "line 9, column 53", {"not valid JSON"});
	require_scene_error(base_with("\"radius\": 1", "\"radius\": Infinity"), "line 9, column 53", {"not valid JSON"});
}

TEST_CASE("A number too large for a float is an error, never an infinity", "[scene][errors]") {
	require_scene_error(base_with("[0, 1, 5]", "[0, 1e999, 5]"), "camera.position[1]", {"expected a finite number"});
	require_scene_error(base_with("[0, 1, 5]", "[0, 1, 1e39]"), "camera.position[2]", {"expected a finite number", "1e+39"});
	require_scene_error(base_with("\"radius\": 1", "\"radius\": -1e999"), "objects[0].radius", {"expected a finite number"});
	require_scene_error(base_with("\"seed\": 7", "\"seed\": 1e999"), "film.seed", {"expected a finite number"});
}

TEST_CASE("A value nested 70 000 deep is an error saying where, never a stack overflow", "[scene][errors]") {
	// The message shows short values in full; a deep one used to be written out recursively.
	// (Not require_scene_error: its report of a failure would print the 140 000 brackets.)
	const size_t depth = 70000;
	const std::string deep = std::string(depth, '[') + std::string(depth, ']');
	Temp_Dir dir;
	for (auto [text, element] : {std::pair{deep, "top level"}, {base_with("[0, 1, 5]", deep), "camera.position"}}) {
		std::string path = write_file(dir, "deep.json", text);
		INFO("a scene whose " << element << " is an array nested " << depth << " deep");
		CHECK_THROWS_WITH(load_scene(path), starts_with_text(path + ": " + element + ": expected ") &&
		                                        contains_text("found an array of 1 element"));
	}
	require_scene_error(base_with("[0, 1, 5]", R"([[0, 1], {"a": [2]}])"), "camera.position",
	                    {R"(found [[0,1],{"a":[2]}])"});
}

TEST_CASE("The scene file itself must exist and hold a JSON object", "[scene][errors]") {
	Temp_Dir dir;
	std::string missing = dir.file("missing.json");
	REQUIRE_THROWS_WITH(load_scene(missing), starts_with_text(missing + ": cannot read the file"));
	REQUIRE_THROWS_WITH(load_scene(dir.path().string()), starts_with_text(dir.path().string() + ": cannot read the file"));
	require_scene_error("[1, 2, 3]", "top level", {"expected an object", "found [1,2,3]"});
}

TEST_CASE("A missing required field names the field and what it should hold", "[scene][errors]") {
	require_scene_error(R"({"materials": {}, "objects": []})", "camera", {"expected an object", "found nothing (the key is missing)"});
	require_scene_error(base_with(R"("position": [0, 1, 5], )", ""), "camera.position", {"expected an array of three numbers", "missing"});
	require_scene_error(base_with(R"(, "vertical_fov": 45)", ""), "camera.vertical_fov", {"expected an angle in degrees between 0 and 180", "missing"});
	require_scene_error(base_with(R"("radius": 1, )", ""), "objects[0].radius", {"expected a number greater than 0", "missing"});
	require_scene_error(base_with(R"("type": "sphere", )", ""), "objects[0].type", {R"(expected "sphere" or "mesh")", "missing"});
	require_scene_error(base_with(R"("material": "white", )", ""), "objects[0].material", {"expected the name of a material", "missing"});
	require_scene_error(base_with(R"(, "triangles": [[0, 1, 2]])", ""), "objects[1].triangles", {"expected an array of triangles", "missing"});
	require_scene_error(base_with(R"("albedo": [0.8, 0.8, 0.8])", R"("albedo_": [0.8, 0.8, 0.8])"), "materials.white.albedo_", {"unknown key"});
	require_scene_error(base_with(R"("type": "emissive", "emission": [4, 4, 4])", R"("type": "emissive")"), "materials.lamp.emission", {"missing"});
}

TEST_CASE("Unknown keys are errors, so a typo is never silently ignored", "[scene][errors]") {
	require_scene_error(base_with(R"("radius": 1)", R"("radious": 1)"), "objects[0].radious", {"unknown key", "radius"});
	require_scene_error(base_with(R"("vertical_fov")", R"("fov")"), "camera.fov", {"unknown key", "vertical_fov"});
	require_scene_error(base_with(R"("samples": 4)", R"("spp": 4)"), "film.spp", {"unknown key", "samples"});
	require_scene_error(base_with(R"("objects": [)", R"("lights": [], "objects": [)"), "lights", {"unknown key", "objects"});
	require_scene_error(base_with(R"({"translate": [0, 1, 0]})", R"({"translate": [0, 1, 0], "rotate": {"axis": [0, 1, 0], "degrees": 1}})"),
	                    "objects[0].transform[0]", {"expected one step"});
	require_scene_error(base_with(R"({"translate": [0, 1, 0]})", R"({"move": [0, 1, 0]})"), "objects[0].transform[0].move", {"unknown key", "translate"});
}

TEST_CASE("A key written twice in one object is an error (JSON parsers would keep only the last)", "[scene][errors]") {
	require_scene_error(base_with(R"("radius": 1)", R"("radius": 1, "radius": 2)"), "objects[0].radius", {"twice"});
	require_scene_error(base_with(R"("lamp": {)", R"("white": {"type": "mirror"}, "lamp": {)"), "materials.white", {"twice"});
}

TEST_CASE("Unknown material, object and environment types list the known ones", "[scene][errors]") {
	require_scene_error(base_with(R"("type": "lambertian")", R"("type": "metal")"), "materials.white.type",
	                    {R"(expected one of "lambertian", "mirror", "glass", "emissive")", R"(found "metal")"});
	require_scene_error(base_with(R"("type": "sphere")", R"("type": "cube")"), "objects[0].type",
	                    {R"(expected "sphere" or "mesh")", R"(found "cube")"});
	require_scene_error(base_with(R"("objects": [)", R"("environment": {"type": "sky"}, "objects": [)"), "environment.type",
	                    {R"(expected "constant" or "image")", R"(found "sky")"});
}

TEST_CASE("An object must refer to a material defined in \"materials\"", "[scene][errors]") {
	require_scene_error(base_with(R"("material": "white")", R"("material": "whte")"), "objects[0].material",
	                    {"expected the name of a material defined in \"materials\" (white, lamp)", R"(found "whte")"});
	require_scene_error(base_with(R"("material": "white")", R"("material": 0)"), "objects[0].material",
	                    {"expected the name of a material", "found 0"});
}

TEST_CASE("Wrong types and array lengths say what was expected and what was found", "[scene][errors]") {
	require_scene_error(base_with("[0, 1, 5]", "[0, 1]"), "camera.position", {"expected an array of three numbers [x, y, z]", "found [0,1]"});
	require_scene_error(base_with("[0, 1, 5]", "[0, 1, 5, 6]"), "camera.position", {"expected an array of three numbers"});
	require_scene_error(base_with("[0, 1, 5]", R"([0, "1", 5])"), "camera.position[1]", {"expected a number", R"(found "1")"});
	require_scene_error(base_with("[0, 1, 5]", "7"), "camera.position", {"expected an array of three numbers", "found 7"});
	require_scene_error(base_with(R"("albedo": [0.8, 0.8, 0.8])", R"("albedo": "red")"), "materials.white.albedo",
	                    {"expected an array of three numbers, each from 0 to 1", R"(found "red")"});
	require_scene_error(base_with(R"("albedo": [0.8, 0.8, 0.8])", R"("albedo": [0.8, 1.5, 0.8])"), "materials.white.albedo[1]",
	                    {"expected a number from 0 to 1", "found 1.5"});
	require_scene_error(base_with(R"("emission": [4, 4, 4])", R"("emission": [4, -4, 4])"), "materials.lamp.emission[1]",
	                    {"expected a number of at least 0", "found -4"});
	require_scene_error(base_with(R"("radius": 1)", R"("radius": "1")"), "objects[0].radius", {"expected a number", R"(found "1")"});
	require_scene_error(base_with(R"("radius": 1)", R"("radius": 0)"), "objects[0].radius", {"expected a number greater than 0", "found 0"});
	const std::string camera = R"("camera": {"position": [0, 0, 0], "target": [0, 0, -1], "vertical_fov": 60})";
	require_scene_error("{" + camera + R"(, "materials": {}, "objects": {"a": 1}})", "objects", {"expected an array of objects", "found an object"});
	require_scene_error("{" + camera + R"(, "materials": [], "objects": []})", "materials",
	                    {"expected an object that maps material names to materials", "found []"});
	require_scene_error(base_with(R"({"type": "sphere")", R"(3, {"type": "sphere")"), "objects[0]", {"expected an object", "found 3"});
	require_scene_error(base_with(R"("max_depth": 5)", R"("max_depth": 2.5)"), "film.max_depth", {"expected a whole number from 0 to 1000", "found 2.5"});
	require_scene_error(base_with(R"("vertical_fov": 45)", R"("vertical_fov": 180)"), "camera.vertical_fov", {"between 0 and 180", "found 180"});
	require_scene_error(base_with(R"("up": [0, 1, 0])", R"("up": [0, 0, -3])"), "camera.up", {"not parallel to the line of sight"});
	require_scene_error(base_with(R"("target": [0, 1, 0])", R"("target": [0, 1, 5])"), "camera.target", {"different from camera.position"});
}

TEST_CASE("The film must have a positive size and at least one sample", "[scene][errors]") {
	require_scene_error(base_with(R"("width": 32)", R"("width": 0)"), "film.width", {"expected a whole number from 1 to 16384", "found 0"});
	require_scene_error(base_with(R"("height": 16)", R"("height": -5)"), "film.height", {"expected a whole number from 1", "found -5"});
	require_scene_error(base_with(R"("samples": 4)", R"("samples": 0)"), "film.samples", {"expected a whole number from 1", "found 0"});
	require_scene_error(base_with(R"("samples": 4)", R"("samples": -1)"), "film.samples", {"expected a whole number from 1", "found -1"});
	require_scene_error(base_with(R"("samples": 4)", R"("samples": 1000001)"), "film.samples", {"from 1 to 1000000", "found 1000001"});
	require_scene_error(base_with(R"("width": 32, "height": 16)", R"("width": 16384, "height": 16384)"), "film",
	                    {"expected at most 16777216 pixels", "16384 x 16384"});
	require_scene_error(base_with(R"("max_depth": 5)", R"("max_depth": 100000)"), "film.max_depth", {"to 1000", "found 100000"});
}

TEST_CASE("Transforms must be invertible, finite and affine", "[scene][errors]") {
	auto with_transform = [](const std::string& steps) {
		return base_with(R"([{"translate": [0, 1, 0]}])", steps);
	};
	require_scene_error(with_transform(R"([{"scale": [1, 0, 1]}])"), "objects[0].transform[0].scale", {"non-zero scale factors", "found [1,0,1]"});
	require_scene_error(with_transform(R"([{"rotate": {"axis": [0, 0, 0], "degrees": 30}}])"), "objects[0].transform[0].rotate.axis", {"a non-zero axis"});
	require_scene_error(with_transform(R"([{"rotate": {"axis": [0, 1, 0]}}])"), "objects[0].transform[0].rotate.degrees", {"missing"});
	require_scene_error(with_transform(R"([{"matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 1, 1]]}])"),
	                    "objects[0].transform[0].matrix[3]", {"[0, 0, 0, 1] (an affine transform)"});
	require_scene_error(with_transform(R"([{"matrix": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}])"), "objects[0].transform[0].matrix",
	                    {"a 4x4 matrix"});
	require_scene_error(with_transform(R"([{"matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 2, 0, 0], [0, 0, 0, 1]]}])"), "objects[0].transform",
	                    {"invertible"});
	require_scene_error(with_transform(R"([{"scale": 1e30}, {"scale": 1e30}])"), "objects[0].transform", {"invertible transform with finite entries"});
	require_scene_error(with_transform(R"({"translate": [0, 1, 0]})"), "objects[0].transform", {"expected an array of steps"});
}

TEST_CASE("Inline meshes need valid vertices, triangles and normals", "[scene][errors]") {
	const std::string mesh = R"("vertices": [[0, 3, 0], [1, 3, 0], [0, 3, 1]], "triangles": [[0, 1, 2]])";
	require_scene_error(base_with(mesh, R"("vertices": [[0, 3, 0], [1, 3, 0], [0, 3, 1]], "triangles": [[0, 1, 3]])"),
	                    "objects[1].triangles[0][2]", {"a vertex index from 0 to 2 (the mesh has 3 vertices)", "found 3"});
	require_scene_error(base_with(mesh, R"("vertices": [[0, 3, 0], [1, 3, 0], [0, 3, 1]], "triangles": [[0, -1, 2]])"),
	                    "objects[1].triangles[0][1]", {"a vertex index from 0 to 2", "found -1"});
	require_scene_error(base_with(mesh, R"("vertices": [[0, 3, 0], [1, 3, 0], [0, 3, 1]], "triangles": [[0, 1]])"),
	                    "objects[1].triangles[0]", {"three vertex indices [i, j, k]", "found [0,1]"});
	require_scene_error(base_with(mesh, R"("vertices": [[0, 3, 0], [1, 3, 0], [0, 3, 1]], "triangles": [])"),
	                    "objects[1].triangles", {"at least one triangle"});
	require_scene_error(base_with(mesh, R"("vertices": [], "triangles": [[0, 1, 2]])"), "objects[1].vertices", {"at least one vertex"});
	require_scene_error(base_with(mesh, mesh + R"(, "normals": [[0, 1, 0]])"), "objects[1].normals",
	                    {"one normal [x, y, z] per vertex (3 of them)", "found [[0,1,0]]"});
	require_scene_error(base_with(mesh, mesh + R"(, "normals": [[0, 1, 0], [0, 0, 0], [0, 1, 0]])"), "objects[1].normals[1]", {"a non-zero normal"});
	require_scene_error(base_with(mesh, mesh + R"(, "file": "x.obj")"), "objects[1]", {"either \"file\" or \"vertices\""});
	require_scene_error(base_with(mesh, mesh + R"(, "flat_shading": 1)"), "objects[1].flat_shading", {"true or false", "found 1"});
}

TEST_CASE("A mesh file that is missing, has no triangles or has bad indices is an error of the scene", "[scene][errors]") {
	Temp_Dir dir;
	auto with_file = [](const std::string& name) {
		return base_with(R"("vertices": [[0, 3, 0], [1, 3, 0], [0, 3, 1]], "triangles": [[0, 1, 2]])", R"("file": ")" + name + "\"");
	};
	std::string mesh_path = dir.file("missing.obj");
	require_scene_error(with_file("missing.obj"), "objects[1].file", {mesh_path + ": cannot read the file"}, &dir);
	std::filesystem::create_directories(dir.path() / "folder.obj");
	require_scene_error(with_file("folder.obj"), "objects[1].file", {dir.file("folder.obj") + ": cannot read the file"}, &dir);
	write_file(dir, "empty.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
	require_scene_error(with_file("empty.obj"), "objects[1].file", {dir.file("empty.obj") + ": no triangles"}, &dir);
	write_file(dir, "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
	require_scene_error(with_file("bad.obj"), "objects[1].file", {dir.file("bad.obj") + ": line 4: face index 4 refers to a vertex"}, &dir);
	require_scene_error(with_file(""), "objects[1].file", {"expected a non-empty string"}, &dir);
}

TEST_CASE("An environment image that is missing or unreadable is an error of the scene", "[scene][errors][image]") {
	Temp_Dir dir;
	auto with_env = [](const std::string& env) {
		return base_with(R"("objects": [)", R"("environment": )" + env + R"(, "objects": [)");
	};
	require_scene_error(with_env(R"({"type": "image", "file": "nowhere.hdr"})"), "environment.file", {dir.file("nowhere.hdr")}, &dir);
	write_file(dir, "garbage.hdr", "this is not a Radiance HDR file\n");
	require_scene_error(with_env(R"({"type": "image", "file": "garbage.hdr"})"), "environment.file", {dir.file("garbage.hdr")}, &dir);
	require_scene_error(with_env(R"({"type": "image"})"), "environment.file", {"expected a non-empty string", "missing"}, &dir);
	require_scene_error(with_env(R"({"type": "constant", "radiance": [1, 1, -1]})"), "environment.radiance[2]", {"at least 0"}, &dir);
	require_scene_error(with_env(R"({"type": "constant", "radiance": [1, 1, 1], "scale": 2})"), "environment.scale", {"unknown key"}, &dir);
}

TEST_CASE("Damaged scene files give an Input_Error naming the file, never a crash or another exception", "[scene][errors][fuzz]") {
	// A small deterministic fuzzer: random edits of a valid scene (deleted, repeated, swapped and
	// replaced characters and numbers). Each result must load or throw Input_Error; anything else
	// (another exception, a crash) fails the test.
	Temp_Dir dir;
	std::string path = dir.file("fuzz.json");
	const std::vector<std::string> inserts{"1e999", "-1", "0", "null", "[]", "{}", "\"", ",", "1e39", "[[0,1,2]]", "-0", "2.5", "true"};
	std::mt19937 rng(20240611);
	size_t loaded = 0, rejected = 0;
	for (int trial = 0; trial < 1500; trial++) {
		std::string text = BASE_SCENE;
		int edits = 1 + int(rng() % 3);
		for (int e = 0; e < edits; e++) {
			size_t at = rng() % text.size();
			size_t length = 1 + rng() % 8;
			switch (rng() % 4) {
			case 0: text.erase(at, length); break;
			case 1: text.insert(at, inserts[rng() % inserts.size()]); break;
			case 2: text.insert(at, text.substr(rng() % text.size(), length)); break;
			default: text[at] = char(32 + rng() % 95); break;
			}
			if (text.empty()) text = "{";
		}
		std::ofstream(path) << text;
		try {
			load_scene(path);
			loaded++;
		} catch (const Input_Error& e) {
			rejected++;
			std::string message = e.what();
			if (message.rfind(path + ": ", 0) != 0) FAIL_CHECK("the message does not start with the file name: " << message);
		} catch (const std::exception& e) {
			FAIL("load_scene threw something other than Input_Error on\n" << text << "\n" << e.what());
		}
	}
	INFO("the edits must exercise both outcomes");
	CHECK(loaded > 0);
	CHECK(rejected > 0);
}

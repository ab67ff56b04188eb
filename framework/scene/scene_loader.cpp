// The JSON scene format (documented with an example in scenes/README.md). Every function reads one
// element and reports a bad value through Json_Element, so each error names the file, the element
// and what was expected.
#include "scene_loader.h"
#include "error.h"
#include "image_io.h"
#include "json_element.h"
#include "scene_objects.h"

#include <algorithm>
#include <limits>

namespace {

// Limits that keep a mistyped film from exhausting memory or the path tracer's stack.
constexpr uint64_t MAX_FILM_SIDE = 16384;
constexpr uint64_t MAX_FILM_PIXELS = Render_Settings::MAX_PIXELS;
constexpr uint64_t MAX_DEPTH = 1000;
constexpr uint64_t MAX_SAMPLES = 1000000; // the same limits as the command line

Render_Settings read_film(const Json_Element& film) {
	Render_Settings settings;
	if (!film.present()) return settings;
	film.allow_only({"width", "height", "samples", "max_depth", "seed"});
	settings.width = uint32_t(film["width"].whole_number_or(1, MAX_FILM_SIDE, settings.width));
	settings.height = uint32_t(film["height"].whole_number_or(1, MAX_FILM_SIDE, settings.height));
	if (uint64_t(settings.width) * settings.height > MAX_FILM_PIXELS) {
		film.error("expected at most " + std::to_string(MAX_FILM_PIXELS) + " pixels (e.g. 4096 x 4096), found " +
		           std::to_string(settings.width) + " x " + std::to_string(settings.height));
	}
	settings.samples = uint32_t(film["samples"].whole_number_or(1, MAX_SAMPLES, settings.samples));
	settings.max_depth = uint32_t(film["max_depth"].whole_number_or(0, MAX_DEPTH, settings.max_depth));
	settings.seed = film["seed"].whole_number_or(0, std::numeric_limits<uint64_t>::max(), settings.seed);
	return settings;
}

Camera read_camera(const Json_Element& camera, const Render_Settings& film) {
	camera.allow_only({"position", "target", "up", "vertical_fov"});
	Vec3 position = camera["position"].vec3();
	Vec3 target = camera["target"].vec3();
	Vec3 up = camera["up"].vec3_or(Vec3{0.0f, 1.0f, 0.0f});
	Json_Element fov_element = camera["vertical_fov"];
	const char* fov_range = "an angle in degrees between 0 and 180 (exclusive)";
	float fov = fov_element.is_number() ? fov_element.number() : 0.0f;
	if (!(fov > 0.0f && fov < 180.0f)) fov_element.fail(fov_range);
	if (position == target) camera["target"].fail("a point different from camera.position");
	if (!is_finite(target - position)) camera["target"].fail("a point at a representable distance from camera.position");
	Camera result = Camera::look_at(position, target, up, fov, float(film.width) / float(film.height));
	// look_at normalizes cross(up, position - target): it has no direction when up is parallel
	// to the line of sight (or zero).
	if (!is_finite(result.camera_to_world)) camera["up"].fail("a non-zero direction not parallel to the line of sight");
	return result;
}

Material read_material(const Json_Element& m) {
	const Vec3 white{1.0f};
	Material material;
	std::string type = m["type"].is_string() ? m["type"].string() : "";
	if (type == "lambertian") {
		m.allow_only({"type", "albedo", "emission"});
		material.bsdf = BSDF_Lambertian{m["albedo"].vec3_in(0.0f, 1.0f)};
	} else if (type == "mirror") {
		m.allow_only({"type", "reflectance", "emission"});
		material.bsdf = BSDF_Mirror{m["reflectance"].vec3_in_or(0.0f, 1.0f, white)};
	} else if (type == "glass") {
		m.allow_only({"type", "index_of_refraction", "reflectance", "transmittance", "emission"});
		BSDF_Glass glass;
		if (m.has("index_of_refraction")) glass.index_of_refraction = m["index_of_refraction"].positive_number();
		glass.reflectance = m["reflectance"].vec3_in_or(0.0f, 1.0f, white);
		glass.transmittance = m["transmittance"].vec3_in_or(0.0f, 1.0f, white);
		material.bsdf = glass;
	} else if (type == "emissive") {
		// A light source: a black Lambertian surface that emits.
		m.allow_only({"type", "emission"});
		material.bsdf = BSDF_Lambertian{Spectrum{0.0f}};
		material.emission = m["emission"].vec3_in(0.0f, INF_F);
	} else {
		m["type"].fail("one of \"lambertian\", \"mirror\", \"glass\", \"emissive\"");
	}
	if (type != "emissive") material.emission = m["emission"].vec3_in_or(0.0f, INF_F, Spectrum{0.0f});
	return material;
}

void read_materials(const Json_Element& materials, Scene& scene) {
	materials.require_object("an object that maps material names to materials");
	for (const auto& [name, value] : materials.json().items()) {
		Json_Element material = materials[name];
		if (name.empty()) material.error("a material needs a non-empty name");
		scene.materials.push_back(read_material(material));
		scene.material_names.push_back(name);
	}
}

void read_objects(const Json_Element& objects, Scene& scene) {
	size_t count = objects.array_size("an array of objects");
	for (size_t i = 0; i < count; i++) scene.objects.push_back(read_object(objects[i], uint32_t(i), scene.material_names));
}

// The image's radiance times `scale`, checked so that it can be looked up and importance-sampled.
HDR_Image read_environment_image(const Json_Element& env, bool importance_sampling) {
	Json_Element file = env["file"];
	HDR_Image image;
	try {
		image = read_image(resolve_file(file));
	} catch (const Input_Error& e) {
		file.error(e.what());
	}
	if (image.w == 0 || image.h == 0 || image.pixels.size() != size_t(image.w) * image.h) file.error("the image is empty");
	float scale = env.has("scale") ? env["scale"].positive_number() : 1.0f;
	for (size_t i = 0; i < image.pixels.size(); i++) {
		Spectrum& pixel = image.pixels[i];
		pixel *= scale;
		if (!is_finite(pixel) || glm::any(glm::lessThan(pixel, Spectrum{0.0f}))) {
			file.error("pixel (" + std::to_string(i % image.w) + ", " + std::to_string(i / image.w) +
			           ") times \"scale\" is not a finite, non-negative radiance");
		}
	}
	double total = total_luminance(image);
	if (!(total < double(std::numeric_limits<float>::max()))) file.error("the image's total luminance overflows a float");
	if (importance_sampling && !(total > 0.0)) {
		file.error("the image is black everywhere, so it cannot be importance-sampled (set \"importance_sampling\": false)");
	}
	return image;
}

Environment read_environment(const Json_Element& env) {
	std::string type = env["type"].is_string() ? env["type"].string() : "";
	if (type == "constant") {
		env.allow_only({"type", "radiance"});
		return Env_Constant{env["radiance"].vec3_in(0.0f, INF_F)};
	}
	if (type == "image") {
		env.allow_only({"type", "file", "scale", "importance_sampling"});
		bool importance_sampling = env["importance_sampling"].boolean_or(true);
		return Env_Map(read_environment_image(env, importance_sampling), importance_sampling);
	}
	env["type"].fail("\"constant\" or \"image\"");
}

Scene read_scene(const Json_Element& root) {
	root.allow_only({"description", "camera", "film", "materials", "objects", "environment"});
	if (root.has("description")) root["description"].string();
	Scene scene;
	scene.path = root.file();
	scene.settings = read_film(root["film"]);
	scene.camera = read_camera(root["camera"], scene.settings);
	read_materials(root["materials"], scene);
	read_objects(root["objects"], scene);
	if (root.has("environment")) scene.environment = read_environment(root["environment"]);
	scene.commit();
	return scene;
}

} // namespace

namespace {

Scene read_scene_of(const Json_Element& root) {
	try {
		return read_scene(root);
	} catch (const Json::exception& e) {
		// Not expected (every value's type is checked before it is read), but never a crash.
		throw Input_Error(root.file() + ": " + e.what());
	}
}

} // namespace

Scene load_scene(const std::string& path) {
	return read_scene_of(Json_Element::parse_file(path));
}

Scene load_scene(const Json& description, const std::string& path) {
	return read_scene_of(Json_Element::from_json(description, path));
}

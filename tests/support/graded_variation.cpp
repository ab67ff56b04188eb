#include "graded_variation.h"

#include "error.h"
#include "estimator.h"
#include "image_io.h"
#include "render.h"
#include "scene_loader.h"
#include "sha256.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <unistd.h>

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

namespace {

float uniform(RNG& rng, float lo, float hi) {
	return lo + (hi - lo) * rng.unit();
}

Json json_of(Vec3 v) {
	return Json::array({v.x, v.y, v.z});
}
Vec3 vec3_of(const Json& j) {
	return Vec3{j.at(0).get<float>(), j.at(1).get<float>(), j.at(2).get<float>()};
}

// Each channel of the colour at `key` (if present) times a factor from [lo, hi].
void scale_colour(Json& material, const char* key, RNG& rng, float lo, float hi) {
	if (!material.contains(key)) return;
	Vec3 colour = vec3_of(material[key]);
	for (int c = 0; c < 3; c++) colour[c] *= uniform(rng, lo, hi);
	material[key] = json_of(colour);
}

Vec3 rotated(Vec3 v, Vec3 axis, float degrees) {
	return Vec3(glm::rotate(Mat4(1.0f), glm::radians(degrees), axis) * Vec4(v, 0.0f));
}

void vary_camera(Json& camera, RNG& rng) {
	Vec3 position = vec3_of(camera.at("position")), target = vec3_of(camera.at("target"));
	Vec3 up = glm::normalize(vec3_of(camera.at("up")));
	Vec3 view = rotated(position - target, up, uniform(rng, -10.0f, 10.0f));
	view = rotated(view, glm::normalize(glm::cross(view, up)), uniform(rng, -4.0f, 4.0f));
	camera["position"] = json_of(target + view);
	camera["vertical_fov"] = camera.at("vertical_fov").get<float>() * uniform(rng, 0.93f, 1.07f);
}

void vary_material(Json& material, RNG& rng) {
	scale_colour(material, "albedo", rng, 0.7f, 1.0f);
	scale_colour(material, "emission", rng, 0.75f, 1.25f);
	if (material.value("type", "") == "mirror") scale_colour(material, "reflectance", rng, 0.7f, 1.0f);
	if (material.value("type", "") == "glass") {
		scale_colour(material, "transmittance", rng, 0.7f, 1.0f);
		material["index_of_refraction"] = uniform(rng, 1.35f, 1.7f);
	}
}

void vary_environment(Json& environment, RNG& rng) {
	if (environment.value("type", "") == "constant") scale_colour(environment, "radiance", rng, 0.75f, 1.25f);
	else environment["scale"] = environment.value("scale", 1.0f) * uniform(rng, 0.75f, 1.25f);
}

// Turns the object about the vertical `up` through `centre` and moves it sideways (transform steps
// appended to its own, so applied after them).
void move_object(Json& object, Vec3 centre, float size, Vec3 up, RNG& rng) {
	Vec3 side = glm::normalize(glm::abs(up.x) < 0.9f ? glm::cross(up, Vec3{1, 0, 0}) : glm::cross(up, Vec3{0, 0, 1}));
	Vec3 shift = rotated(side, up, uniform(rng, 0.0f, 360.0f)) * uniform(rng, 0.0f, 0.15f * size);
	Json steps = object.value("transform", Json::array());
	steps.push_back({{"translate", json_of(-centre)}});
	steps.push_back({{"rotate", {{"axis", json_of(up)}, {"degrees", uniform(rng, -20.0f, 20.0f)}}}});
	steps.push_back({{"translate", json_of(centre + shift)}});
	object["transform"] = steps;
}

Json read_description(const std::string& file) {
	std::ifstream in(file);
	if (!in) throw Input_Error(file + ": cannot be read");
	return Json::parse(in);
}

} // namespace

Json vary_graded_scene(const Graded_Scene& graded, RNG& rng) {
	Scene loaded = load_graded(graded); // its checksum verified, its objects' bounds known
	Json description = read_description(graded_scene_file(graded.name));
	Vec3 up = glm::normalize(vec3_of(description.at("camera").at("up")));
	vary_camera(description["camera"], rng);
	for (auto& [name, material] : description["materials"].items()) vary_material(material, rng);
	if (description.contains("environment")) vary_environment(description["environment"], rng);

	std::map<uint32_t, BBox> bounds; // by object index
	BBox scene_bounds;
	for (const Instance& object : loaded.bvh.primitives) {
		bounds[object.index] = object.bbox();
		scene_bounds.enclose(object.bbox());
	}
	const float scene_size = glm::length(scene_bounds.max - scene_bounds.min);
	Json& objects = description["objects"];
	for (uint32_t i = 0; i < objects.size(); i++) {
		const BBox& box = bounds.at(i);
		float size = glm::length(box.max - box.min);
		bool sphere = objects[i].value("type", "") == "sphere";
		if (sphere || size < 0.5f * scene_size) move_object(objects[i], 0.5f * (box.min + box.max), size, up, rng);
	}
	return description;
}

namespace {

// The passes merged, but for pass `skip` (none if skip >= passes.size()).
Film merged(const std::vector<Film>& passes, size_t skip) {
	Film film(passes[0].w, passes[0].h);
	for (size_t p = 0; p < passes.size(); p++) {
		if (p == skip) continue;
		for (size_t i = 0; i < film.pixels.size(); i++) film.pixels[i].merge(passes[p].pixels[i]);
	}
	return film;
}

Judge_Reference render_reference(const Graded_Scene& graded, const Scene& scene, const Render_Settings& grader,
                                 const std::string& integrator) {
	Render_Settings settings = grader;
	settings.samples = grader.samples * REFERENCE_SPP_FACTOR;
	settings.seed = REFERENCE_SEED;
	Pathtracer pathtracer(scene, settings, graded.view, Estimator_Choice{integrator});
	std::vector<Film> passes;
	for (uint32_t p = 1; p <= REFERENCE_SPP_FACTOR; p++) {
		Render_Options options;
		options.pass = p;
		options.passes = REFERENCE_SPP_FACTOR;
		passes.push_back(render(pathtracer, options));
	}
	Judge_Reference made;
	made.reference = Image_Estimate::from(merged(passes, passes.size()));
	made.calibration.renders = REFERENCE_SPP_FACTOR;
	made.calibration.z_critical = outlier_z(size_t(grader.width) * grader.height);
	for (size_t p = 0; p < passes.size(); p++) {
		Image_Estimate others = Image_Estimate::from(merged(passes, p));
		made.calibration.outliers += count_outliers(Image_Estimate::from(passes[p], grader.samples), others);
	}
	return made;
}

const char* view_word(View view) {
	return view == View::eye_light ? "eye" : "path";
}

} // namespace

Judge_Reference judge_reference(const Graded_Scene& graded, const Json& description, const Render_Settings& grader,
                                const std::string& integrator) {
	// What made it, whose SHA-256 names it in the cache.
	Json made_of{{"format", 1},
	             {"scene", description},
	             {"view", view_word(graded.view)},
	             {"width", grader.width},
	             {"height", grader.height},
	             {"max_depth", grader.max_depth},
	             {"samples", grader.samples},
	             {"integrator", integrator},
	             {"reference_factor", REFERENCE_SPP_FACTOR},
	             {"reference_seed", REFERENCE_SEED}};
	const char* cache_dir = std::getenv("LAB_REFERENCE_CACHE");
	fs::path cache = cache_dir ? fs::path(cache_dir) / sha256_of_bytes(made_of.dump()) : fs::path();
	auto file = [&](const char* suffix) { return cache.string() + suffix; };
	if (!cache.empty() && fs::exists(file(".json"))) {
		Json record = Json::parse(std::ifstream(file(".json")));
		Judge_Reference kept;
		kept.reference = Image_Estimate::uniform(read_image(file("_mean.exr")), read_image(file("_var.exr")),
		                                         read_image(file("_m4.exr")), record.at("spp"));
		kept.calibration = Image_Calibration{record.at("renders"), record.at("outliers"), record.at("z_critical")};
		return kept;
	}
	Scene scene = load_scene(description, graded_scene_file(graded.name));
	Judge_Reference made = render_reference(graded, scene, grader, integrator);
	if (cache.empty()) return made;
	// Written under names of this process's own, then renamed into place, the record last: a reader
	// sees a whole entry or none, whatever other judges write at the same time.
	std::error_code error;
	fs::create_directories(cache.parent_path(), error);
	fs::permissions(cache.parent_path(), fs::perms::owner_all, error);
	std::string mine = "." + std::to_string(getpid());
	write_exr(file("_mean.exr") + mine, made.reference.mean);
	write_exr(file("_var.exr") + mine, made.reference.variance);
	write_exr(file("_m4.exr") + mine, made.reference.fourth);
	Json record{{"spp", grader.samples * REFERENCE_SPP_FACTOR}, {"renders", made.calibration.renders},
	            {"outliers", made.calibration.outliers}, {"z_critical", made.calibration.z_critical},
	            {"made_of", made_of}};
	std::ofstream(file(".json") + mine) << record.dump(1, '\t') << "\n";
	for (const char* suffix : {"_mean.exr", "_var.exr", "_m4.exr", ".json"}) {
		fs::rename(file(suffix) + mine, file(suffix), error);
	}
	return made;
}

#include "graded_images.h"

#include "error.h"
#include "estimator.h"
#include "image_io.h"
#include "scene_loader.h"
#include "sha256.h"

#include <fstream>
#include <nlohmann/json.hpp>

const std::vector<Graded_Scene>& graded_scenes() {
	static const std::vector<Graded_Scene> scenes{
		{"eye_bunny", View::eye_light},        // tasks 1-3
		{"cornell_diffuse", View::path},       // task 4
		{"glass_balls", View::path},           // task 5
		{"cornell_small_light", View::path, {"mixture", "nee"}}, // task 6 and its extension
		{"env_overcast", View::path},          // task 7
	};
	return scenes;
}

const Graded_Scene& graded_scene(const std::string& name) {
	for (const Graded_Scene& scene : graded_scenes()) {
		if (scene.name == name) return scene;
	}
	throw Input_Error("no graded scene named '" + name + "' (see tests/support/graded_images.cpp)");
}

std::string graded_scene_file(const std::string& name) {
	return "scenes/graded/" + name + ".json";
}

std::string reference_file(const std::string& name, const std::string& suffix) {
	return "scenes/graded/references/" + name + suffix;
}

Scene load_graded(const Graded_Scene& graded) {
	verify_checksum(graded_scene_file(graded.name));
	return load_scene(graded_scene_file(graded.name));
}

namespace {

// The files whose checksums make_references records: every graded scene and its references.
std::vector<std::string> checked_files() {
	std::vector<std::string> files;
	for (const Graded_Scene& scene : graded_scenes()) {
		files.push_back(graded_scene_file(scene.name));
		for (const char* suffix : {".json", "_mean.exr", "_var.exr", "_m4.exr"}) {
			files.push_back(reference_file(scene.name, suffix));
		}
	}
	return files;
}

} // namespace

void record_checksums() {
	std::string text;
	for (const std::string& file : checked_files()) text += sha256_of_file(file) + "  " + file + "\n";
	std::ofstream(GRADED_CHECKSUMS) << text;
}

void verify_checksum(const std::string& file, const std::string& checksums) {
	std::ifstream in(checksums);
	if (!in) throw Input_Error(checksums + ": missing; run `./lab references` to record the checksums");
	std::string sum, name;
	while (in >> sum >> name) {
		if (name != file) continue;
		if (sha256_of_file(file) == sum) return;
		throw Input_Error(file + ": its contents differ from what `./lab references` recorded in " + checksums +
		                  " (checksum mismatch): restore it (git checkout) or, if the change is deliberate, run "
		                  "`./lab references`");
	}
	throw Input_Error(file + ": has no checksum in " + checksums + "; run `./lab references`");
}

Film render_graded(const Graded_Scene& graded, const Scene& scene, uint32_t samples, uint64_t seed,
                   const Render_Options& options) {
	Render_Settings settings = scene.settings;
	settings.samples = samples;
	settings.seed = seed;
	Pathtracer pathtracer(scene, settings, graded.view);
	return render(pathtracer, options);
}

namespace {
nlohmann::ordered_json read_record(const Graded_Scene& scene) {
	std::string record_file = reference_file(scene.name, ".json");
	std::ifstream in(record_file);
	if (!in) throw Input_Error(record_file + ": missing; run `./lab references` to make the reference images");
	return nlohmann::ordered_json::parse(in);
}
} // namespace

Image_Calibration read_calibration(const Graded_Scene& scene, const Render_Settings& grader,
                                   const std::string& integrator) {
	std::string record_file = reference_file(scene.name, ".json");
	verify_checksum(record_file);
	nlohmann::ordered_json record = read_record(scene);
	for (const auto& entry : record.value("outliers", nlohmann::ordered_json::array())) {
		if (entry.at("integrator") != integrator || entry.at("samples") != grader.samples) continue;
		return Image_Calibration{entry.at("renders"), entry.at("outliers"), entry.at("z_critical")};
	}
	throw Input_Error(record_file + ": no outlier counts of renders with " + std::to_string(grader.samples) +
	                  " samples and --integrator " + integrator + "; run `./lab references`");
}

Image_Estimate read_reference(const Graded_Scene& scene, const Render_Settings& grader) {
	std::string record_file = reference_file(scene.name, ".json");
	for (const char* suffix : {".json", "_mean.exr", "_var.exr", "_m4.exr"}) {
		verify_checksum(reference_file(scene.name, suffix));
	}
	nlohmann::ordered_json record = read_record(scene);
	if (record.at("view") != view_name(scene.view) || record.at("width") != grader.width ||
	    record.at("height") != grader.height || record.at("max_depth") != grader.max_depth) {
		throw Input_Error(record_file + ": made with other settings than " + graded_scene_file(scene.name) +
		                  " now has; run `./lab references`");
	}
	return Image_Estimate::uniform(read_image(reference_file(scene.name, "_mean.exr")),
	                               read_image(reference_file(scene.name, "_var.exr")),
	                               read_image(reference_file(scene.name, "_m4.exr")), record.at("spp"));
}

void write_reference(const Graded_Scene& scene, const Film& film, const Render_Settings& settings) {
	write_exr(reference_file(scene.name, "_mean.exr"), film.mean());
	write_exr(reference_file(scene.name, "_var.exr"), film.variance());
	write_exr(reference_file(scene.name, "_m4.exr"), film.fourth_moment());
	nlohmann::ordered_json record{{"scene", graded_scene_file(scene.name)}, {"view", view_name(scene.view)},
	                              {"width", film.w}, {"height", film.h},
	                              {"max_depth", settings.max_depth}, {"spp", settings.samples},
	                              {"seed", settings.seed},
	                              {"made_by", "./lab references (tests/images/make_references.cpp)"}};
	std::ofstream(reference_file(scene.name, ".json")) << record.dump(1, '\t') << "\n";
}

void count_reference_outliers(const Graded_Scene& scene, const std::function<void(size_t, size_t)>& progress) {
	Scene loaded = load_scene(graded_scene_file(scene.name)); // its checksum is recorded after
	nlohmann::ordered_json record = read_record(scene);
	Image_Estimate reference =
		Image_Estimate::uniform(read_image(reference_file(scene.name, "_mean.exr")),
		                        read_image(reference_file(scene.name, "_var.exr")),
		                        read_image(reference_file(scene.name, "_m4.exr")), record.at("spp"));
	nlohmann::ordered_json counts = nlohmann::ordered_json::array();
	size_t done = 0, total = OUTLIER_RENDERS * scene.integrators.size();
	for (const std::string& integrator : scene.integrators) {
		Render_Settings settings = loaded.settings;
		uint64_t outliers = 0;
		for (uint32_t r = 0; r < OUTLIER_RENDERS; r++) {
			Render_Options options;
			options.threads = 0; // every core
			settings.seed = OUTLIER_SEED + r;
			Film film = render(Pathtracer(loaded, settings, scene.view, Estimator_Choice{integrator}), options);
			outliers += count_outliers(Image_Estimate::from(film, settings.samples), reference);
			if (progress) progress(++done, total);
		}
		counts.push_back({{"integrator", integrator}, {"samples", settings.samples},
		                  {"renders", OUTLIER_RENDERS}, {"outliers", outliers},
		                  {"z_critical", outlier_z(size_t(settings.width) * settings.height)}});
	}
	record["outliers"] = counts;
	std::ofstream(reference_file(scene.name, ".json")) << record.dump(1, '\t') << "\n";
}

Reference_Check compare_with_reference(const Graded_Scene& scene, const Film& film, const Render_Settings& settings,
                                       const std::string& integrator, double alpha) {
	return compare_with(film, settings, read_reference(scene, settings), read_calibration(scene, settings, integrator),
	                    alpha);
}

Reference_Check compare_with(const Film& film, const Render_Settings& settings, Image_Estimate reference,
                             const Image_Calibration& calibration, double alpha) {
	Image_Estimate render = Image_Estimate::from(film, settings.samples); // the samples asked for
	Image_Comparison comparison = compare_images(render, reference, calibration, alpha);
	return Reference_Check{comparison, film.non_finite(), std::move(render), std::move(reference)};
}

Reference_Check check_against_reference(const Graded_Scene& scene, std::optional<uint64_t> seed) {
	Render_Options options;
	options.threads = 2;
	Scene loaded = load_graded(scene);
	uint64_t render_seed = seed.value_or(loaded.settings.seed);
	Film film = render_graded(scene, loaded, loaded.settings.samples, render_seed, options);
	return compare_with_reference(scene, film, loaded.settings, "mixture");
}

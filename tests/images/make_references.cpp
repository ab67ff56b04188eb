// `./lab references`: renders every graded scene (scenes/graded/) with the reference implementation
// at REFERENCE_SPP_FACTOR times the graders' samples and writes scenes/graded/references/. For
// instructors; run it after changing a graded scene, then run `./lab test` (label images).
//
//   make_references [SCENE...]                  render and write the references (default: all)
//   make_references --checksums                 only record the checksums of the files as they are
//   make_references --pass P/N --passes DIR [SCENE...]
//                                               render pass P of N of each reference into DIR (one
//                                               machine's share, e.g. one task of a Slurm array)
//   make_references --merge --passes DIR [SCENE...]
//                                               merge the N passes in DIR into the references
//
// A reference made from N passes is the one rendered whole, up to the order of the sums (the passes
// draw every sample once, framework/film/film_file.h). Every reference written is then checked against
// OUTLIER_RENDERS renders of the reference with the graders' settings and seeds of their own, whose
// outlier pixels its record keeps (image_compare.h: how many a correct render has). Every run that
// writes a reference ends by recording the SHA-256 of every graded scene and reference file
// (graded_images.h), which the graders verify. Run from the repository root.
#include "error.h"
#include "film_file.h"
#include "graded_images.h"
#include "terminal.h"

#include <chrono>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct Arguments {
	bool checksums_only = false, merge = false;
	std::optional<std::pair<uint32_t, uint32_t>> pass; // P, N
	std::string passes_dir;
	std::vector<std::string> scenes; // empty: all
};

std::pair<uint32_t, uint32_t> parse_pass(const std::string& text) {
	size_t slash = text.find('/');
	try {
		if (slash != std::string::npos) {
			unsigned long p = std::stoul(text.substr(0, slash)), n = std::stoul(text.substr(slash + 1));
			if (p >= 1 && p <= n && n <= 100000) return {uint32_t(p), uint32_t(n)};
		}
	} catch (const std::exception&) {
	}
	throw Input_Error("--pass: expected P/N with 1 <= P <= N (e.g. 3/8), got '" + text + "'");
}

Arguments parse(int argc, char** argv) {
	Arguments a;
	for (int i = 1; i < argc; i++) {
		std::string arg = argv[i];
		auto value = [&]() {
			if (i + 1 == argc) throw Input_Error(arg + " needs a value");
			return std::string(argv[++i]);
		};
		if (arg == "--checksums") a.checksums_only = true;
		else if (arg == "--merge") a.merge = true;
		else if (arg == "--pass") a.pass = parse_pass(value());
		else if (arg == "--passes") a.passes_dir = value();
		else if (arg.rfind("--", 0) == 0) throw Input_Error("unknown option '" + arg + "'");
		else a.scenes.push_back(arg);
	}
	if ((a.pass || a.merge) && a.passes_dir.empty()) throw Input_Error("--pass and --merge need --passes DIR");
	if (a.pass && a.merge) throw Input_Error("--pass renders a share, --merge merges the shares: give one of them");
	return a;
}

Render_Settings reference_settings(const Scene& loaded) {
	Render_Settings settings = loaded.settings;
	settings.samples *= REFERENCE_SPP_FACTOR;
	settings.seed = REFERENCE_SEED;
	return settings;
}

Film render_reference(const Graded_Scene& scene, const Scene& loaded, const Render_Settings& settings, uint32_t pass,
                      uint32_t passes) {
	Progress_Bar bar(std::cerr, stderr_is_terminal());
	Render_Options options;
	options.tile_size = 8; // more tiles: a smoother progress bar
	options.progress = [&](size_t done, size_t total) { bar.update(done, total); };
	options.pass = pass, options.passes = passes;
	return render_graded(scene, loaded, settings.samples, settings.seed, options);
}

std::string pass_file(const std::string& dir, const std::string& scene, uint32_t pass, uint32_t passes) {
	return (fs::path(dir) / (scene + ".pass-" + std::to_string(pass) + "-of-" + std::to_string(passes) + ".exr")).string();
}

// Every pass file of `scene` in `dir`.
std::vector<std::string> pass_files(const std::string& dir, const std::string& scene) {
	std::vector<std::string> files;
	if (fs::is_directory(dir)) {
		for (const auto& entry : fs::directory_iterator(dir)) {
			std::string name = entry.path().filename().string();
			if (name.rfind(scene + ".pass-", 0) == 0) files.push_back(entry.path().string());
		}
	}
	if (files.empty()) throw Input_Error(dir + ": no passes of " + scene + " (" + scene + ".pass-P-of-N.exr)");
	return files;
}

// The outliers of correct renders, into the reference's record (graded_images.h).
void count_outliers_of(const Graded_Scene& scene) {
	auto start = std::chrono::steady_clock::now();
	Progress_Bar bar(std::cerr, stderr_is_terminal());
	count_reference_outliers(scene, [&](size_t done, size_t total) { bar.update(done, total); });
	std::cerr << "  counted the outliers of " << OUTLIER_RENDERS * scene.integrators.size() << " correct renders in "
	          << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s\n";
}

void make_reference(const Graded_Scene& scene, const Arguments& a) {
	Scene loaded = load_graded(scene);
	Render_Settings settings = reference_settings(loaded);
	auto start = std::chrono::steady_clock::now();
	auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
	if (a.merge) {
		Film_File merged = merge_films(pass_files(a.passes_dir, scene.name));
		if (merged.origin.samples != settings.samples || merged.origin.seed != settings.seed) {
			throw Input_Error(a.passes_dir + ": the passes of " + scene.name + " have " + std::to_string(merged.origin.samples) +
			                  " samples and seed " + std::to_string(merged.origin.seed) + "; its reference needs " +
			                  std::to_string(settings.samples) + " and " + std::to_string(settings.seed));
		}
		write_reference(scene, merged.film, settings);
		std::cerr << scene.name << ": merged the passes into " << reference_file(scene.name, "_{mean,var,m4}.exr, .json")
		          << "\n";
		count_outliers_of(scene);
		return;
	}
	auto [pass, passes] = a.pass.value_or(std::pair<uint32_t, uint32_t>{1, 1});
	std::cerr << scene.name << ": " << settings.width << " x " << settings.height << ", " << settings.samples
	          << " spp, seed " << settings.seed;
	if (a.pass) std::cerr << ", pass " << pass << " of " << passes;
	std::cerr << "\n";
	Film film = render_reference(scene, loaded, settings, pass, passes);
	if (film.non_finite() != 0) std::cerr << "  warning: " << film.non_finite() << " non-finite samples\n";
	if (a.pass) {
		std::string file = pass_file(a.passes_dir, scene.name, pass, passes);
		write_film(file, film, Film_Origin{scene.name, settings.seed, settings.samples, pass, passes});
		std::cerr << "  wrote " << file << " in " << seconds() << " s\n";
		return;
	}
	write_reference(scene, film, settings);
	std::cerr << "  wrote " << reference_file(scene.name, "_{mean,var,m4}.exr, .json") << " in " << seconds() << " s\n";
	count_outliers_of(scene);
}

} // namespace

int main(int argc, char** argv) {
	try {
		Arguments a = parse(argc, argv);
		if (!a.checksums_only) {
			std::vector<const Graded_Scene*> scenes;
			for (const Graded_Scene& scene : graded_scenes()) {
				if (a.scenes.empty()) scenes.push_back(&scene);
			}
			for (const std::string& name : a.scenes) scenes.push_back(&graded_scene(name));
			for (const Graded_Scene* scene : scenes) make_reference(*scene, a);
		}
		if (a.pass) return 0; // the references are written by --merge
		record_checksums();
		std::cerr << "recorded the checksums in scenes/graded/references/SHA256SUMS\n";
	} catch (const std::exception& e) {
		std::cerr << "make_references: " << e.what() << "\n";
		return 1;
	}
}

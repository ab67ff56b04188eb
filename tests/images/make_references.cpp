// `./lab references`: renders every graded scene (scenes/graded/) with the reference implementation
// at REFERENCE_SPP_FACTOR times the graders' samples and writes scenes/graded/references/. For
// instructors; run it after changing a graded scene, then run `./lab test` (label images).
// Arguments: the names of the scenes to redo (default: all), or --checksums to only record the
// checksums of the files as they are. Either way it ends by recording the SHA-256 of every graded
// scene and reference file (graded_images.h), which the graders verify. Run from the repository root.
#include "graded_images.h"
#include "terminal.h"

#include <chrono>
#include <iostream>
#include <string>

namespace {
void make_reference(const Graded_Scene& scene) {
	Scene loaded = load_graded(scene);
	Render_Settings settings = loaded.settings;
	settings.samples *= REFERENCE_SPP_FACTOR;
	settings.seed = REFERENCE_SEED;
	std::cerr << scene.name << ": " << settings.width << " x " << settings.height << ", " << settings.samples
	          << " spp, seed " << settings.seed << "\n";
	auto start = std::chrono::steady_clock::now();
	Film film = [&] {
		Progress_Bar bar(std::cerr, stderr_is_terminal());
		Render_Options options;
		options.tile_size = 8; // more tiles: a smoother progress bar
		options.progress = [&](size_t done, size_t total) { bar.update(done, total); };
		return render_graded(scene, loaded, settings.samples, settings.seed, options);
	}();
	if (film.non_finite() != 0) std::cerr << "  warning: " << film.non_finite() << " non-finite samples\n";
	write_reference(scene, film, settings);
	std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
	std::cerr << "  wrote " << reference_file(scene.name, "_{mean,var}.exr, .json") << " in " << seconds.count()
	          << " s\n";
}
} // namespace

int main(int argc, char** argv) {
	try {
		bool checksums_only = argc == 2 && std::string(argv[1]) == "--checksums";
		if (argc == 1) {
			for (const Graded_Scene& scene : graded_scenes()) make_reference(scene);
		}
		for (int i = 1; i < argc && !checksums_only; i++) make_reference(graded_scene(argv[i]));
		record_checksums();
		std::cerr << "recorded the checksums in scenes/graded/references/SHA256SUMS\n";
	} catch (const std::exception& e) {
		std::cerr << "make_references: " << e.what() << "\n";
		return 1;
	}
}

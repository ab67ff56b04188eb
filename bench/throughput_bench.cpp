// The render throughput benchmark: for each shipped scene, samples per second on one thread and on
// all cores (their ratio is the scaling), where one thread's time goes (closest-hit queries, light
// sampling, the rest), and how soon a tiny scene's first pixel is done after the process starts.
// Usage: throughput_bench [SCENE...] [--spp N] [--repeats N]. See README.md.
#include "bench_timing.h"
#include "render.h"
#include "scene_loader.h"
#include "time_profile.h"

#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

extern char** environ;

namespace {

struct Options {
	std::vector<std::string> scenes; // default: scenes/*.json
	uint32_t spp = 0;                // 0: each scene's own
	int repeats = 5;
};

Options parse(int argc, char** argv) {
	Options options;
	for (int i = 1; i < argc; i++) {
		std::string arg = argv[i];
		bool has_value = i + 1 < argc;
		if (arg == "--spp" && has_value) options.spp = uint32_t(std::max(1, std::atoi(argv[++i])));
		else if (arg == "--repeats" && has_value) options.repeats = std::max(1, std::atoi(argv[++i]));
		else if (arg == "-h" || arg == "--help") {
			std::printf("usage: throughput_bench [SCENE...] [--spp N] [--repeats N]\n");
			std::exit(0);
		} else options.scenes.push_back(arg);
	}
	if (options.scenes.empty()) {
		for (const auto& entry : std::filesystem::directory_iterator("scenes"))
			if (entry.path().extension() == ".json") options.scenes.push_back(entry.path().string());
		std::sort(options.scenes.begin(), options.scenes.end());
	}
	return options;
}

double seconds(Time_Profile::Clock::duration d) {
	return std::chrono::duration<double>(d).count();
}

// Wall time of a render of `pathtracer` on `threads` threads; the image goes to `film`.
double timed_render(const Pathtracer& pathtracer, uint32_t threads, Film& film) {
	Render_Options options;
	options.threads = threads;
	auto start = std::chrono::steady_clock::now();
	film = render(pathtracer, options);
	return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Scene_Result {
	double load = 0;                       // seconds: parsing, meshes, BVHs
	std::vector<double> one, all;          // wall seconds per repeat
	double tracing = 0, light_sampling = 0; // fractions of the profiled one-thread render
	double profiled = 0;                   // seconds of the profiled render
	double rays_per_sample = 0;
	bool same_image = true; // one thread and all cores must agree bit for bit
};

Scene_Result measure(const std::string& path, const Options& options, uint32_t threads, Render_Settings& settings) {
	Scene_Result result;
	auto start = std::chrono::steady_clock::now();
	Scene scene = load_scene(path);
	result.load = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	settings = scene.settings;
	if (options.spp) settings.samples = options.spp;
	Pathtracer pathtracer(scene, settings);

	Film single(1, 1), parallel(1, 1);
	for (int repeat = 0; repeat < options.repeats; repeat++) { // taking turns, as the load changes
		result.one.push_back(timed_render(pathtracer, 1, single));
		result.all.push_back(timed_render(pathtracer, threads, parallel));
		result.same_image = result.same_image && single.mean().pixels == parallel.mean().pixels;
	}
	Time_Profile profile; // one thread: render() works on this one, where the profile is active
	result.profiled = timed_render(pathtracer, 1, single);
	Time_Profile::Clock::duration overhead = Time_Profile::clock_overhead();
	result.tracing = seconds(Time_Profile::net(profile.closest_hits, overhead)) / result.profiled;
	result.light_sampling = seconds(Time_Profile::net(profile.light_samples, overhead) +
	                                Time_Profile::net(profile.light_pdfs, overhead)) /
	                        result.profiled;
	result.rays_per_sample =
		double(profile.closest_hits.count) / (double(settings.width) * settings.height * settings.samples);
	return result;
}

// Wall time from starting the renderer on a 1 x 1 film, 1 sample, to its exit: an upper bound on
// the time from process start to the first finished pixel.
double first_pixel_seconds(const std::string& scene) {
	std::string out = (std::filesystem::temp_directory_path() / "lab_first_pixel.png").string();
	std::vector<std::string> args{LAB_RENDERER, scene, "--width", "1", "--height", "1", "--spp", "1",
	                              "--threads", "1", "--quiet", "--out", out};
	std::vector<char*> argv;
	for (std::string& arg : args) argv.push_back(arg.data());
	argv.push_back(nullptr);
	auto start = std::chrono::steady_clock::now();
	pid_t pid;
	if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) {
		std::printf("ERROR: cannot start %s\n", argv[0]);
		std::exit(1);
	}
	int status = 0;
	waitpid(pid, &status, 0);
	double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
		std::printf("ERROR: %s %s failed\n", argv[0], scene.c_str());
		std::exit(1);
	}
	return elapsed;
}

constexpr double SCALING_TARGET = 1.85;
constexpr double FIRST_PIXEL_TARGET = 0.020; // seconds
const char* const TINY_SCENE = "scenes/furnace.json";

} // namespace

int main(int argc, char** argv) {
	Options options = parse(argc, argv);
	uint32_t threads = std::max(1u, std::thread::hardware_concurrency());
	std::printf("render throughput, reference implementation; %d repeats, medians; all cores = %u threads\n\n",
	            options.repeats, threads);
	std::printf("%-24s %-13s %7s | %10s %10s %7s | %9s %8s %8s %6s\n", "scene", "film", "load s", "1 thread",
	            "all cores", "scaling", "rays/spl", "tracing", "lights", "other");
	std::printf("%-24s %-13s %7s | %21s %7s | %9s %24s\n", "", "", "", "Msamples/s (wall)", "", "",
	            "one thread's time in");

	int status = 0;
	std::vector<double> scalings, overheads;
	for (const std::string& path : options.scenes) {
		Render_Settings settings;
		Scene_Result r = measure(path, options, threads, settings);
		double samples = double(settings.width) * settings.height * settings.samples;
		double scaling = median(r.one) / median(r.all);
		scalings.push_back(scaling);
		overheads.push_back(r.profiled / median(r.one) - 1);
		char film[32];
		std::snprintf(film, sizeof film, "%ux%u %u spp", settings.width, settings.height, settings.samples);
		std::printf("%-24s %-13s %7.2f | %10.2f %10.2f %6.2fx | %9.2f %7.0f%% %7.0f%% %5.0f%%\n",
		            std::filesystem::path(path).filename().c_str(), film, r.load, samples / median(r.one) * 1e-6,
		            samples / median(r.all) * 1e-6, scaling, r.rays_per_sample, 100 * r.tracing,
		            100 * r.light_sampling, 100 * (1 - r.tracing - r.light_sampling));
		if (!r.same_image) {
			std::printf("ERROR: %s: the image on %u threads differs from the one on one thread\n", path.c_str(), threads);
			status = 1;
		}
	}
	std::printf("(lights: sample_area_lights and area_lights_pdf; other: BSDFs, the estimator, camera rays, film.\n"
	            " Timing one call in %d made the profiled render %.0f%% slower, median over the scenes; the clock's\n"
	            " own share of the timed calls is taken out of tracing and lights.)\n\n",
	            int(Time_Profile::TIMED_EVERY), 100 * median(overheads));
	std::printf("scaling to %u threads: median %.2fx over %zu scenes, lowest %.2fx (target >= %.2fx)\n", threads,
	            median(scalings), scalings.size(), *std::min_element(scalings.begin(), scalings.end()),
	            SCALING_TARGET);

	std::vector<double> starts;
	for (int i = 0; i < 11; i++) starts.push_back(first_pixel_seconds(TINY_SCENE));
	double first = median(starts);
	std::printf("first pixel: %s on a 1x1 film, process start to exit, median of 11: %.1f ms (target <= %.0f ms)\n",
	            TINY_SCENE, first * 1e3, FIRST_PIXEL_TARGET * 1e3);
	return status;
}

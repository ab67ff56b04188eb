// Every shipped scene rendered by the lab's reference renderer and by Blender Cycles
// (bench/cycles/render_in_cycles.py) with the scene's own film and depth, both at high spp as two
// independent halves whose difference estimates each pixel's noise: the whole-image relMSE between
// the two against what their noise alone gives, and the means of a 4 x 4 grid of regions per colour
// channel with z-scores. `./lab bench cycles-accuracy --help`; bench/README.md.
#include "bench_usage.h"
#include "cycles/renderer_runs.h"
#include "image_io.h"
#include "significance.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

constexpr uint32_t GRID = 4;       // regions per side
constexpr double FAMILY_ALPHA = 0.01; // per scene, over its GRID x GRID x 3 region tests (Sidak)

struct Options {
	std::vector<std::string> scenes;
	uint32_t spp = 512, threads = 2;
	uint64_t seed = 1; // the halves' seeds: seed and seed + 1
	bool cycles_defaults = false;
	std::vector<std::string> cycles_options; // passed on to render_in_cycles.py
	std::vector<std::string> lab_options;    // passed on to our renderer
	std::string out = "bench/results", images = LAB_BENCH_BINARY_DIR "/cycles_accuracy";
};

const Bench_Usage USAGE{"cycles_accuracy_bench",
	"usage: cycles_accuracy_bench [SCENE...] [--spp N] [--threads T] [--seed S] [--cycles-defaults]\n"
	"                             [--cycles-option OPTION]... [--lab-option OPTION]... [--out DIR]\n"
	"\n"
	"Renders each SCENE (default: every scenes/*.json) with the lab's reference renderer and with Blender\n"
	"Cycles at the scene's film and max depth, N spp each (default 512) as two halves with seeds S and S + 1\n"
	"(default S: 1), on T threads (default 2). Per scene: the whole image's mean per channel, Cycles / ours - 1\n"
	"with its standard error; the relMSE between the two images and what their noise alone would give; the\n"
	"means of a 4 x 4 grid of regions per channel, z = (Cycles - ours) / standard error, and how many exceed\n"
	"the critical |z| (Sidak, 1% per scene), each listed by column and row (0 0 the top left), channel,\n"
	"difference and z. --cycles-defaults: first, scenes/cornell_box.json with each group of Cycles' own\n"
	"defaults that render_in_cycles.py overrides (bounces, clamp, light-threshold, filter), alone and all\n"
	"together. --cycles-option OPTION: pass OPTION on to render_in_cycles.py (e.g. --light-as-mesh);\n"
	"--lab-option OPTION: pass OPTION on to our renderer (e.g. --light-choice power).\n"
	"The render times are of runs that share the machine: no speed measurement (./lab bench cycles).\n"
	"Writes DIR/cycles_accuracy.md (default DIR: bench/results) and both images of each scene as EXR under\n"
	"the build directory.\n"};

Options parse(int argc, char** argv) {
	Options o;
	for (int i = 1; i < argc; i++) {
		std::string arg = argv[i];
		USAGE.help_if_asked(arg);
		if (arg == "--cycles-defaults") {
			o.cycles_defaults = true;
		} else if (arg == "--spp" || arg == "--threads" || arg == "--seed" || arg == "--out" || arg == "--cycles-option" || arg == "--lab-option") {
			std::string value = USAGE.value_of(i, argc, argv);
			if (arg == "--out") {
				o.out = value;
				continue;
			}
			if (arg == "--cycles-option" || arg == "--lab-option") {
				(arg == "--cycles-option" ? o.cycles_options : o.lab_options).push_back(value);
				continue;
			}
			if (arg == "--seed") {
				o.seed = USAGE.whole_number(arg, value, 0);
				continue;
			}
			(arg == "--spp" ? o.spp : o.threads) = USAGE.whole_number(arg, value, arg == "--spp" ? 2 : 1);
		} else if (arg.rfind("--", 0) == 0) {
			USAGE.error("unknown option '" + arg + "'");
		} else {
			if (!std::filesystem::is_regular_file(arg)) USAGE.error("no such scene file: " + arg);
			o.scenes.push_back(arg);
		}
	}
	if (o.scenes.empty()) {
		for (const auto& entry : std::filesystem::directory_iterator("scenes"))
			if (entry.path().extension() == ".json") o.scenes.push_back(entry.path().string());
		std::sort(o.scenes.begin(), o.scenes.end());
	}
	return o;
}

struct Rendered {
	Noisy_Image image;
	double render_seconds = 0.0;
};

Rendered render_halves(Renderer renderer, const std::string& scene, const Options& o, const std::string& work_dir,
                       const std::vector<std::string>& cycles_defaults = {}) {
	Rendered r;
	HDR_Image halves[2];
	for (uint64_t half = 0; half < 2; half++) {
		Renderer_Run run = run_renderer(renderer, {scene, o.spp / 2, o.seed + half, o.threads, 0, cycles_defaults, o.cycles_options, o.lab_options}, work_dir);
		halves[half] = std::move(run.image);
		r.render_seconds += run.render_seconds;
	}
	r.image = from_two_halves(halves[0], halves[1]);
	return r;
}

// The mean of channel c over pixels [x0, x1) x [y0, y1) and the variance of that mean.
struct Region_Mean {
	double mean = 0.0, variance = 0.0;
};
Region_Mean region_mean(const Noisy_Image& image, int c, uint32_t x0, uint32_t x1, uint32_t y0, uint32_t y1) {
	Region_Mean m;
	double n = double(x1 - x0) * double(y1 - y0);
	for (uint32_t y = y0; y < y1; y++)
		for (uint32_t x = x0; x < x1; x++) {
			m.mean += image.mean.at(x, y)[c] / n;
			m.variance += image.variance.at(x, y)[c] / (n * n); // pixels are independent
		}
	return m;
}

struct Comparison {
	std::string whole_means; // per channel: Cycles / ours - 1, with its standard error
	double rel_mse = 0.0, rel_mse_noise = 0.0;
	uint32_t beyond = 0;
	std::string beyond_list; // each region beyond: column row channel, difference, z
	double largest_z = 0.0, largest_difference = 0.0; // over the regions: the largest |z| and its relative difference
	std::string largest_where;                            // its column, row and channel
};

Comparison compare(const Noisy_Image& ours, const Noisy_Image& cycles) {
	if (ours.mean.w != cycles.mean.w || ours.mean.h != cycles.mean.h)
		throw std::runtime_error("the two renders have different sizes");
	Comparison result;
	uint32_t w = ours.mean.w, h = ours.mean.h;
	for (int c = 0; c < 3; c++) {
		Region_Mean a = region_mean(ours, c, 0, w, 0, h), b = region_mean(cycles, c, 0, w, 0, h);
		double se = std::sqrt(a.variance + b.variance) / a.mean;
		result.whole_means += (c ? " / " : "") + fmt("%+.2f", 100.0 * (b.mean / a.mean - 1.0)) + fmt(" ± %.2f", 100.0 * se);
	}
	result.rel_mse = rel_mse(cycles.mean, ours.mean);
	result.rel_mse_noise = noise_rel_mse(ours, ours.mean) + noise_rel_mse(cycles, ours.mean);
	double critical = stats::two_sided_z(stats::sidak(FAMILY_ALPHA, GRID * GRID * 3));
	for (uint32_t gy = 0; gy < GRID; gy++)
		for (uint32_t gx = 0; gx < GRID; gx++)
			for (int c = 0; c < 3; c++) {
				uint32_t x0 = w * gx / GRID, x1 = w * (gx + 1) / GRID, y0 = h * gy / GRID, y1 = h * (gy + 1) / GRID;
				Region_Mean a = region_mean(ours, c, x0, x1, y0, y1), b = region_mean(cycles, c, x0, x1, y0, y1);
				double se = std::sqrt(a.variance + b.variance);
				double z = se > 0 ? (b.mean - a.mean) / se : (b.mean == a.mean ? 0.0 : INFINITY);
				if (std::abs(z) > critical) {
					result.beyond++;
					result.beyond_list += std::string(result.beyond_list.empty() ? "" : "; ") + std::to_string(gx) + " " +
					                      std::to_string(gy) + " " + "RGB"[c] + " " +
					                      fmt("%+.2f %%, z %.1f", a.mean > 0 ? 100.0 * (b.mean / a.mean - 1.0) : 0.0, z);
				}
				if (std::abs(z) > std::abs(result.largest_z)) {
					result.largest_z = z;
					result.largest_difference = a.mean > 0 ? b.mean / a.mean - 1.0 : 0.0;
					result.largest_where = std::to_string(gx) + " " + std::to_string(gy) + " " + "RGB"[c];
				}
			}
	return result;
}

int run(const Options& o) {
	std::string work_dir = std::filesystem::temp_directory_path() / ("lab_cycles_accuracy_" + std::to_string(getpid()));
	std::filesystem::create_directories(work_dir);
	std::filesystem::create_directories(o.images);
	std::filesystem::create_directories(o.out);
	std::string load_before = load_average();
	double critical = stats::two_sided_z(stats::sidak(FAMILY_ALPHA, GRID * GRID * 3));
	std::printf("Cycles against ours on %zu scenes, %u spp each (two halves), %u threads; load average: %s\n",
	            o.scenes.size(), o.spp, o.threads, load_before.c_str());
	std::string table =
		"| scene | Cycles / ours − 1, whole image, R / G / B (%, ± standard error) | relMSE (noise alone) | regions "
		"beyond |z| " + fmt("%.2f", critical) + " of " + std::to_string(GRID * GRID * 3) +
		" | largest |z| (its difference, column row channel) | render s, ours / Cycles |\n|---|---|---|---|---|---|\n";
	auto start = std::chrono::steady_clock::now();
	std::string variants_table, options;
	for (const std::string& option : o.cycles_options) options += " " + option;
	std::string lab_options;
	for (const std::string& option : o.lab_options) lab_options += " " + option;
	// Rewritten after every row, so that a run cut short keeps what it measured.
	auto write_table = [&] {
		std::string header = "Each scene at its own film and max depth, " + std::to_string(o.spp) +
		                     " spp per renderer (two halves, seeds " + std::to_string(o.seed) + " and " + std::to_string(o.seed + 1) + "), " + std::to_string(o.threads) + " threads; " +
		                     (options.empty() ? "" : "render_in_cycles.py with" + options + "; ") +
		                     (lab_options.empty() ? "" : "ours with" + lab_options + "; ") + "load average " + load_before + " at the start, " + load_average() + " at this row; " +
		                     fmt("%.0f s so far.", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()) +
		                     "\n\n";
		std::ofstream(o.out + "/cycles_accuracy.md") << header << variants_table << table;
	};
	if (o.cycles_defaults) {
		const std::string scene = "scenes/cornell_box.json";
		std::printf("%s with Cycles' own defaults:\n", scene.c_str());
		variants_table = "`" + scene + "` with Cycles' own defaults for what render_in_cycles.py matches, against ours:\n\n"
		                 "| Cycles' default kept | Cycles / ours − 1, whole image, R / G / B (%) | relMSE (noise alone) |\n|---|---|---|\n";
		Rendered ours = render_halves(Renderer::lab, scene, o, work_dir);
		std::vector<std::vector<std::string>> variants{
			{}, {"bounces"}, {"clamp"}, {"light-threshold"}, {"filter"}, {"bounces", "clamp", "light-threshold", "filter"}};
		for (const auto& variant : variants) {
			std::string label;
			for (const std::string& v : variant) label += (label.empty() ? "" : ", ") + v;
			Rendered cycles = render_halves(Renderer::cycles, scene, o, work_dir, variant);
			Comparison c = compare(ours.image, cycles.image);
			std::string row = "| " + (label.empty() ? std::string("none (matched)") : label) + " | " + c.whole_means + " | " +
			                  fmt("%.3g (%.3g)", c.rel_mse, c.rel_mse_noise) + " |\n";
			variants_table += row;
			std::printf("%s", row.c_str());
			std::fflush(stdout);
			write_table();
		}
		variants_table += "\n";
	}
	for (const std::string& scene : o.scenes) {
		std::string name = std::filesystem::path(scene).stem().string();
		std::printf("%s ...", name.c_str());
		std::fflush(stdout);
		try {
			Rendered ours = render_halves(Renderer::lab, scene, o, work_dir);
			Rendered cycles = render_halves(Renderer::cycles, scene, o, work_dir);
			write_exr(o.images + "/" + name + "_ours.exr", ours.image.mean);
			write_exr(o.images + "/" + name + "_cycles.exr", cycles.image.mean);
			Comparison c = compare(ours.image, cycles.image);
			std::string row = "| `" + name + "` | " + c.whole_means + " | " + fmt("%.3g (%.3g)", c.rel_mse, c.rel_mse_noise) +
			                  " | " + std::to_string(c.beyond) + (c.beyond ? " (" + c.beyond_list + ")" : "") + " | " +
			                  fmt("%.1f (%+.2f %%, ", c.largest_z, 100.0 * c.largest_difference) + c.largest_where + ") | " +
			                  fmt("%.1f / %.1f", ours.render_seconds, cycles.render_seconds) + " |\n";
			table += row;
			std::printf(" %s", row.c_str());
		} catch (const std::exception& e) {
			table += "| `" + name + "` | not compared: " + e.what() + " |||||\n";
			std::printf(" not compared: %s\n", e.what());
		}
		std::fflush(stdout);
		write_table();
	}
	std::filesystem::remove_all(work_dir);
	write_table();
	std::printf("\nwrote %s/cycles_accuracy.md and the images in %s\n", o.out.c_str(), o.images.c_str());
	return 0;
}

} // namespace

int main(int argc, char** argv) {
	try {
		return run(parse(argc, argv));
	} catch (const std::exception& e) {
		std::fprintf(stderr, "error: %s\n", e.what());
		return 1;
	}
}

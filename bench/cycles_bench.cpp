// Blender Cycles beside the lab's reference renderer in one run: both render the same scene (the
// Cornell box by default, max depth 100, 2 threads) at the same spp ladder, interleaved, each as the
// command a user runs; relMSE against one reference of each renderer (two independent halves, whose
// difference estimates the reference's own noise); time to relMSE 1e-3 from the command's start and
// from the render time alone; and both again with their own adaptive sampling, over a ladder of
// thresholds, with the bias adaptive sampling leaves in the image's mean. Several scenes: one after
// another, then a summary of them. `./lab bench cycles --help`; bench/README.md.
#include "bench_timing.h"
#include "bench_usage.h"
#include "convergence_metrics.h"
#include "convergence_plot.h"
#include "cycles/renderer_runs.h"
#include "image_io.h"
#include "text_file.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

constexpr double TARGET_REL_MSE = 1e-3;
const Renderer RENDERERS[] = {Renderer::lab, Renderer::cycles};

struct Options {
	std::vector<std::string> scenes; // in the order given; none: the Cornell box
	std::vector<uint32_t> ladder{16, 32, 64, 128, 256};
	uint32_t repeats = 3, reference_spp = 4096, threads = 2, max_depth = 100;
	std::string out = "bench/results", cache = LAB_BENCH_BINARY_DIR "/cycles_cache";
	std::vector<std::string> cycles_options; // passed on to render_in_cycles.py, e.g. --light-as-mesh
	// Adaptive sampling, each renderer's own: ours --adaptive T (a pixel's relative 95 % half-width),
	// Cycles' noise threshold; at most adaptive_spp samples a pixel (0: 4 x the ladder's largest).
	std::vector<double> ours_thresholds{0.25, 0.177, 0.125, 0.088, 0.0625};
	std::vector<double> cycles_thresholds{0.16, 0.08, 0.04, 0.02, 0.01};
	uint32_t adaptive_spp = 0;
	bool adaptive = true;
};

const Bench_Usage USAGE{"cycles_bench",
	"usage: cycles_bench [SCENE...] [--spp-ladder N,N,...] [--repeats N] [--reference-spp N] [--max-depth D]\n"
	"                    [--threads T] [--cycles-option OPTION]... [--out DIR]\n"
	"                    [--adaptive-ladder T,T,...] [--cycles-adaptive-ladder T,T,...] [--adaptive-spp N] [--no-adaptive]\n"
	"\n"
	"Renders SCENE (default scenes/cornell_box.json; its film size) with the lab's reference renderer and with\n"
	"Blender Cycles (bench/cycles/render_in_cycles.py: matched settings), at max depth D (default 100; 0: the\n"
	"scene's) on T threads (default 2), --repeats times (default 3) at each spp of the ladder (default\n"
	"16,32,64,128,256), in a shuffled order, the two renderers taking turns. Each run is timed from the\n"
	"command's start to its exit, and by the render time the renderer reports. relMSE is measured against\n"
	"each renderer's own reference of --reference-spp samples (default 4096, two halves with other seeds;\n"
	"cached under the build directory: delete it after changing a renderer); the reference's noise is\n"
	"subtracted. Prints and writes DIR/cycles_time_to_error.{md,csv,svg} (default DIR: bench/results):\n"
	"time to relMSE 1e-3 for both renderers, the efficiency 1 / (relMSE * seconds), their ratio, and the\n"
	"load average before and after. --cycles-option OPTION: pass OPTION on to render_in_cycles.py (e.g.\n"
	"--light-as-mesh: the Cornell box's light as a mesh light, as before issue 26's export fixes).\n"
	"Then both again with their own adaptive sampling, at most --adaptive-spp samples a pixel (default 4 x the\n"
	"ladder's largest), over a ladder of thresholds: ours --adaptive T (default 0.25,0.177,0.125,0.088,0.0625),\n"
	"Cycles' noise threshold (default 0.16,0.08,0.04,0.02,0.01); time to relMSE 1e-3 along each, and the\n"
	"bias of the image's mean against the renderer's own reference. --no-adaptive: the uniform renders only.\n"
	"Several SCENEs: one after another, each through all of the above with the same options; a scene other\n"
	"than the Cornell box writes DIR/cycles_time_to_error_<scene file stem>.{md,csv,svg}. Then a summary, one\n"
	"row per scene: the uniform times to 1e-3 against Cycles' reference, ours, Cycles' and ours / Cycles, from\n"
	"the command's start and in render time; printed and written to DIR/cycles_time_to_error_scenes.md.\n"};

std::vector<double> threshold_ladder(const std::string& option, const std::string& value) {
	std::vector<double> ladder;
	for (size_t start = 0; start <= value.size();) {
		size_t comma = std::min(value.find(',', start), value.size());
		std::string text = value.substr(start, comma - start);
		char* end = nullptr;
		double t = std::strtod(text.c_str(), &end);
		if (text.empty() || *end != '\0' || !(t > 0.0 && t <= 1.0)) {
			USAGE.error(option + " takes thresholds in (0, 1] separated by commas, e.g. 0.25,0.125");
		}
		ladder.push_back(t);
		start = comma + 1;
	}
	std::sort(ladder.rbegin(), ladder.rend()); // the loosest first: fewest samples
	if (ladder.size() < 2) USAGE.error(option + " needs two thresholds or more");
	return ladder;
}

// Where a scene's results go, without the extension: DIR/cycles_time_to_error for the Cornell box (as
// ever), DIR/cycles_time_to_error_<scene file stem> for any other.
std::string results_path(const std::string& out, const std::string& scene) {
	std::string stem = std::filesystem::path(scene).stem().string();
	return out + "/cycles_time_to_error" + (stem == "cornell_box" ? "" : "_" + stem);
}

Options parse(int argc, char** argv) {
	Options o;
	for (int i = 1; i < argc; i++) {
		std::string arg = argv[i];
		USAGE.help_if_asked(arg);
		if (arg == "--no-adaptive") {
			o.adaptive = false;
			continue;
		}
		if (arg.rfind("--", 0) != 0) {
			o.scenes.push_back(arg);
			continue;
		}
		std::string value = USAGE.value_of(i, argc, argv);
		if (arg == "--repeats") o.repeats = USAGE.whole_number(arg, value, 1);
		else if (arg == "--reference-spp") o.reference_spp = USAGE.whole_number(arg, value, 2);
		else if (arg == "--max-depth") o.max_depth = USAGE.whole_number(arg, value, 0);
		else if (arg == "--threads") o.threads = USAGE.whole_number(arg, value, 1);
		else if (arg == "--out") o.out = value;
		else if (arg == "--cycles-option") o.cycles_options.push_back(value);
		else if (arg == "--adaptive-ladder") o.ours_thresholds = threshold_ladder(arg, value);
		else if (arg == "--cycles-adaptive-ladder") o.cycles_thresholds = threshold_ladder(arg, value);
		else if (arg == "--adaptive-spp") o.adaptive_spp = USAGE.whole_number(arg, value, 16);
		else if (arg == "--spp-ladder") {
			o.ladder.clear();
			for (size_t start = 0; start <= value.size();) {
				size_t comma = std::min(value.find(',', start), value.size());
				o.ladder.push_back(USAGE.whole_number(arg, value.substr(start, comma - start), 1));
				start = comma + 1;
			}
			std::sort(o.ladder.begin(), o.ladder.end());
			if (o.ladder.size() < 2) USAGE.error("--spp-ladder needs two spp or more, e.g. 16,32,64");
		} else USAGE.error("unknown option '" + arg + "'");
	}
	if (o.scenes.empty()) o.scenes.push_back("scenes/cornell_box.json");
	for (size_t i = 0; i < o.scenes.size(); i++) {
		if (!std::filesystem::is_regular_file(o.scenes[i])) USAGE.error("no such scene file: " + o.scenes[i]);
		for (size_t j = 0; j < i; j++) {
			if (std::filesystem::equivalent(o.scenes[j], o.scenes[i])) USAGE.error("scene given twice: " + o.scenes[i]);
			if (results_path(o.out, o.scenes[j]) == results_path(o.out, o.scenes[i]))
				USAGE.error(o.scenes[j] + " and " + o.scenes[i] + " would write the same files (the same file name)");
		}
	}
	if (o.ours_thresholds.size() != o.cycles_thresholds.size()) {
		USAGE.error("--adaptive-ladder and --cycles-adaptive-ladder need as many thresholds each");
	}
	if (o.adaptive_spp == 0) o.adaptive_spp = 4 * o.ladder.back();
	return o;
}

double mean(const std::vector<double>& values) {
	double sum = 0.0;
	for (double v : values) sum += v;
	return sum / double(values.size());
}

// ---- References ---------------------------------------------------------------------------------

// A renderer's high-spp image as two halves (seeds 1000001 and 1000002), cached under a name made
// from what it depends on.
Noisy_Image reference(Renderer renderer, const std::string& scene, const Options& o, const std::string& work_dir) {
	std::string identity = read_text_file(scene) + "|" + read_text_file(LAB_CYCLES_SCRIPT) + "|" +
	                       std::to_string(o.reference_spp) + "|" + std::to_string(o.max_depth);
	for (const std::string& option : o.cycles_options) identity += "|" + option;
	char key[32];
	std::snprintf(key, sizeof key, "%016zx", std::hash<std::string>{}(identity));
	std::filesystem::create_directories(o.cache);
	std::vector<HDR_Image> halves;
	for (uint64_t half = 1; half <= 2; half++) {
		std::string path = o.cache + "/" + (renderer == Renderer::lab ? "lab_" : "cycles_") + key + "_" +
		                   std::to_string(half) + ".exr";
		if (!std::filesystem::exists(path)) {
			Render_Request request{scene, o.reference_spp / 2, 1000000 + half, o.threads, o.max_depth, {}, o.cycles_options, {}};
			Renderer_Run run = run_renderer(renderer, request, work_dir);
			std::printf("  %s reference half %llu: %u spp in %.0f s\n", renderer_name(renderer),
			            static_cast<unsigned long long>(half), request.spp, run.command_seconds);
			std::fflush(stdout);
			write_exr(path, run.image);
		}
		halves.push_back(read_image(path));
	}
	return from_two_halves(halves[0], halves[1]);
}

// ---- One renderer's series ----------------------------------------------------------------------

// A series of runs: one renderer, uniform (a ladder of spp) or adaptive (a ladder of thresholds at
// Options::adaptive_spp).
struct Series {
	Renderer renderer;
	bool adaptive;
};
const Series SERIES[] = {{Renderer::lab, false}, {Renderer::cycles, false}, {Renderer::lab, true}, {Renderer::cycles, true}};

std::string series_name(const Series& series) {
	return std::string(renderer_name(series.renderer)) + (series.adaptive ? ", adaptive" : "");
}

struct Run_Result {
	size_t step; // in the series' ladder
	double command_seconds, render_seconds, mean_spp;
	double rel_mse[2];         // against our reference, against Cycles'
	double mean_difference[2]; // the image's mean against the reference's, relative
};

struct Curve {
	std::vector<double> x; // per step: spp (uniform) or threshold (adaptive)
	std::vector<double> command_seconds, render_seconds, rel_mse, mean_spp; // medians of times and spp, mean relMSE
	std::vector<double> bias, bias_error; // the image's mean against the reference's: mean over the repeats, its standard error
	double slope = 0, spp_to_target = 0, command_to_target = 0, render_to_target = 0, efficiency = 0, ms_per_spp = 0;
};

// The x at which the least-squares line of log y on log x reaches y = target.
double fitted_x_at(const std::vector<double>& x, const std::vector<double>& y, double target) {
	double slope = log_log_slope(x, y), mean_u = 0.0, mean_v = 0.0;
	for (size_t i = 0; i < x.size(); i++) {
		mean_u += std::log(x[i]) / double(x.size());
		mean_v += std::log(y[i]) / double(x.size());
	}
	return std::exp(mean_u + (std::log(target) - mean_v) / slope);
}

// The least-squares line y = a + b x, evaluated at `at`: a run's time is a fixed cost plus a cost per
// sample (Blender's start-up, loading and the BVH are the fixed cost of a command).
double linear_fit_at(const std::vector<double>& x, const std::vector<double>& y, double at) {
	double n = double(x.size()), mean_x = 0.0, mean_y = 0.0;
	for (size_t i = 0; i < x.size(); i++) {
		mean_x += x[i] / n;
		mean_y += y[i] / n;
	}
	double covariance = 0.0, spread = 0.0;
	for (size_t i = 0; i < x.size(); i++) {
		covariance += (x[i] - mean_x) * (y[i] - mean_y);
		spread += (x[i] - mean_x) * (x[i] - mean_x);
	}
	return mean_y + covariance / spread * (at - mean_x);
}

// `against`: 0 our reference, 1 Cycles'; `noise`: that reference's share of every relMSE. A uniform
// series reaches the target along spp (relMSE ~ 1/spp, times a fixed cost plus a cost per sample); an
// adaptive one along its thresholds, where neither law holds: its time to the target is where the
// line of log relMSE on log seconds reaches it.
Curve fit(const std::vector<Run_Result>& runs, const std::vector<double>& ladder, bool adaptive, int against, double noise) {
	Curve c;
	std::vector<double> efficiency;
	for (size_t step = 0; step < ladder.size(); step++) {
		std::vector<double> command, render, error, spp, difference;
		for (const Run_Result& r : runs) {
			if (r.step != step) continue;
			command.push_back(r.command_seconds);
			render.push_back(r.render_seconds);
			error.push_back(r.rel_mse[against]);
			spp.push_back(r.mean_spp);
			difference.push_back(r.mean_difference[against]);
		}
		c.x.push_back(ladder[step]);
		c.command_seconds.push_back(median(command));
		c.render_seconds.push_back(median(render));
		c.rel_mse.push_back(std::max(mean(error) - noise, 1e-12));
		c.mean_spp.push_back(adaptive ? median(spp) : ladder[step]);
		double m = mean(difference), spread = 0.0;
		for (double d : difference) spread += (d - m) * (d - m);
		c.bias.push_back(m);
		c.bias_error.push_back(difference.size() > 1 ? std::sqrt(spread / double(difference.size() - 1) / double(difference.size())) : 0.0);
		efficiency.push_back(1.0 / (c.rel_mse.back() * c.render_seconds.back()));
	}
	c.efficiency = median(efficiency);
	if (adaptive) {
		c.slope = log_log_slope(c.render_seconds, c.rel_mse);
		c.render_to_target = fitted_x_at(c.render_seconds, c.rel_mse, TARGET_REL_MSE);
		c.command_to_target = fitted_x_at(c.command_seconds, c.rel_mse, TARGET_REL_MSE);
		return c;
	}
	c.slope = log_log_slope(c.x, c.rel_mse);
	c.spp_to_target = fitted_x_at(c.x, c.rel_mse, TARGET_REL_MSE);
	c.command_to_target = linear_fit_at(c.x, c.command_seconds, c.spp_to_target);
	c.render_to_target = linear_fit_at(c.x, c.render_seconds, c.spp_to_target);
	c.ms_per_spp = 1000.0 * c.render_seconds.back() / c.x.back(); // at the largest spp, where the fixed costs weigh least
	return c;
}

std::string fixed(double value, int digits) {
	char text[64];
	std::snprintf(text, sizeof text, "%.*f", digits, value);
	return text;
}

std::string general(double value) {
	char text[64];
	std::snprintf(text, sizeof text, "%.3g", value);
	return text;
}

// The mean of an image's pixel channels.
double image_mean(const HDR_Image& image) {
	double sum = 0.0;
	for (const Spectrum& p : image.pixels) sum += double(p.r) + p.g + p.b;
	return sum / (3.0 * double(image.pixels.size()));
}

std::string joined(const std::vector<double>& values, const std::function<std::string(double)>& show) {
	std::string text;
	for (size_t i = 0; i < values.size(); i++) text += (i ? " / " : "") + show(values[i]);
	return text;
}

// What the summary of several scenes needs of one: the uniform series against Cycles' reference.
struct Scene_Result {
	Curve ours, cycles;
	bool written;
};

// The whole procedure on one scene: references, the timed renders, the fits; prints and writes its
// tables, the renders' CSV and the plot.
Scene_Result run_scene(const std::string& scene, const Options& o) {
	std::string work_dir = std::filesystem::temp_directory_path() / ("lab_cycles_bench_" + std::to_string(getpid()));
	std::filesystem::create_directories(work_dir);
	std::string load_before = load_average();
	std::printf("Cycles beside ours: %s, max depth %u, %u threads; load average at the start: %s\n", scene.c_str(),
	            o.max_depth, o.threads, load_before.c_str());
	std::printf("references (%u spp each, two halves; cached in %s):\n", o.reference_spp, o.cache.c_str());
	std::fflush(stdout);
	Noisy_Image references[2] = {reference(Renderer::lab, scene, o, work_dir), reference(Renderer::cycles, scene, o, work_dir)};
	double noise[2] = {noise_rel_mse(references[0], references[0].mean), noise_rel_mse(references[1], references[1].mean)};
	double reference_means[2] = {image_mean(references[0].mean), image_mean(references[1].mean)};
	double references_apart = rel_mse(references[1].mean, references[0].mean);
	std::printf("the references' own noise adds %.3g (ours) and %.3g (Cycles') to every relMSE; subtracted\n"
	            "the two references differ by relMSE %.3g (their noise alone: %.3g)\n",
	            noise[0], noise[1], references_apart, noise[0] + noise[1]);

	// The ladders: spp (uniform), thresholds (adaptive, ours and Cycles' step by step).
	std::vector<double> spp_ladder(o.ladder.begin(), o.ladder.end());
	auto ladder_of = [&](const Series& series) -> const std::vector<double>& {
		if (!series.adaptive) return spp_ladder;
		return series.renderer == Renderer::lab ? o.ours_thresholds : o.cycles_thresholds;
	};
	auto request_for = [&](const Series& series, size_t step, uint64_t seed) {
		Render_Request request{scene, o.ladder[std::min(step, o.ladder.size() - 1)], seed, o.threads, o.max_depth, {},
		                       o.cycles_options, {}};
		if (!series.adaptive) return request;
		request.spp = o.adaptive_spp;
		std::string threshold = general(ladder_of(series)[step]);
		if (series.renderer == Renderer::lab) request.lab_options = {"--adaptive", threshold};
		else request.cycles_options.insert(request.cycles_options.end(), {"--adaptive-threshold", threshold});
		return request;
	};

	// A job: one step of the uniform or the adaptive ladders, one seed; both renderers render it, taking turns.
	struct Job {
		bool adaptive;
		size_t step;
		uint64_t seed;
	};
	std::vector<Job> jobs;
	uint64_t seed = 1;
	for (bool adaptive : {false, true}) {
		if (adaptive && !o.adaptive) continue;
		size_t steps = adaptive ? o.ours_thresholds.size() : o.ladder.size();
		for (size_t step = 0; step < steps; step++)
			for (uint32_t i = 0; i < o.repeats; i++) jobs.push_back({adaptive, step, seed++});
	}
	std::shuffle(jobs.begin(), jobs.end(), std::mt19937(12345));

	std::filesystem::create_directories(o.out);
	std::string results_base = results_path(o.out, scene);
	std::ofstream csv(results_base + ".csv");
	csv << "renderer,adaptive,spp,threshold,seed,command_seconds,render_seconds,mean_spp,relmse_vs_ours,relmse_vs_cycles,"
	       "mean_difference_vs_own\n";
	std::vector<Run_Result> results[4];
	std::string load_ladder = load_average();
	std::printf("rendering %zu images per renderer, taking turns (load average %s)...", jobs.size(), load_ladder.c_str());
	std::fflush(stdout);
	auto start = std::chrono::steady_clock::now();
	for (size_t j = 0; j < jobs.size(); j++) {
		for (size_t turn = 0; turn < 2; turn++) {
			size_t k = (j + turn) % 2 + (jobs[j].adaptive ? 2 : 0); // who goes first alternates
			const Series& series = SERIES[k];
			Render_Request request = request_for(series, jobs[j].step, jobs[j].seed);
			Renderer_Run run = run_renderer(series.renderer, request, work_dir);
			double mean = image_mean(run.image);
			Run_Result r{jobs[j].step, run.command_seconds, run.render_seconds, run.mean_spp,
			             {rel_mse(run.image, references[0].mean), rel_mse(run.image, references[1].mean)},
			             {mean / reference_means[0] - 1.0, mean / reference_means[1] - 1.0}};
			results[k].push_back(r);
			int own = series.renderer == Renderer::lab ? 0 : 1;
			csv << renderer_name(series.renderer) << "," << series.adaptive << "," << request.spp << ","
			    << (series.adaptive ? ladder_of(series)[jobs[j].step] : 0.0) << "," << jobs[j].seed << ","
			    << r.command_seconds << "," << r.render_seconds << "," << r.mean_spp << "," << r.rel_mse[0] << ","
			    << r.rel_mse[1] << "," << r.mean_difference[own] << "\n";
		}
	}
	std::string load_after = load_average();
	std::printf(" %.0f s; load average at the end: %s\n",
	            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), load_after.c_str());
	std::filesystem::remove_all(work_dir);

	// Against Cycles' reference (the independent anchor), and against ours beside it.
	size_t series_count = o.adaptive ? 4 : 2;
	Curve curves[4][2]; // [series][against]
	for (size_t k = 0; k < series_count; k++)
		for (int a = 0; a < 2; a++) curves[k][a] = fit(results[k], ladder_of(SERIES[k]), SERIES[k].adaptive, a, noise[a]);

	std::string table, joined_options;
	for (const std::string& option : o.cycles_options) joined_options += " " + option;
	table += "Scene `" + scene + "`, film as in the scene, max depth " + std::to_string(o.max_depth) + ", " +
	         std::to_string(o.threads) + " threads; " + std::to_string(o.repeats) + " renders per spp and renderer; " +
	         (o.cycles_options.empty() ? "" : "render_in_cycles.py with" + joined_options + "; ") +
	         "load average (1, 5, 15 min) " + load_before + " at the start, " + load_ladder + " when the timed renders began, " +
	         load_after + " at the end.\n\n";
	table += "| renderer | reference | relMSE at";
	for (uint32_t spp : o.ladder) table += " " + std::to_string(spp);
	table += " spp | slope | command s at each spp | render s at each spp | ms per spp | spp to 1e-3 | "
	         "s to 1e-3 (command) | s to 1e-3 (render) | efficiency (render) |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
	for (int a : {1, 0})
		for (int k = 0; k < 2; k++) {
			const Curve& c = curves[k][a];
			table += std::string("| ") + renderer_name(SERIES[k].renderer) + " | " + (a ? "Cycles'" : "ours") + " | " +
			         joined(c.rel_mse, general) + " | " + fixed(c.slope, 2) + " | " +
			         joined(c.command_seconds, [](double v) { return fixed(v, 2); }) + " | " +
			         joined(c.render_seconds, [](double v) { return fixed(v, 2); }) + " | " + fixed(c.ms_per_spp, 1) +
			         " | " + fixed(c.spp_to_target, 0) + " | " + fixed(c.command_to_target, 2) + " s | " +
			         fixed(c.render_to_target, 2) + " s | " + fixed(c.efficiency, 0) + " |\n";
		}
	const Curve &ours = curves[0][1], &cycles = curves[1][1];
	table += "\nAgainst Cycles' reference: ours reaches relMSE 1e-3 " +
	         fixed(cycles.command_to_target / ours.command_to_target, 2) + "x as fast as Cycles from the command's start (" +
	         fixed(ours.command_to_target, 2) + " s against " + fixed(cycles.command_to_target, 2) + " s), " +
	         fixed(cycles.render_to_target / ours.render_to_target, 2) + "x in render time alone (" +
	         fixed(ours.render_to_target, 2) + " s against " + fixed(cycles.render_to_target, 2) + " s); efficiency ratio " +
	         fixed(ours.efficiency / cycles.efficiency, 2) + "x. The references differ by relMSE " +
	         general(references_apart) + ".\n\n(relMSE: mean over the renders, minus the reference's own noise; "
	         "command: wall time from the command's start to its exit, median; render: the time the renderer reports "
	         "(ours: rendering; Cycles: the render call, scene sync and BVH included); spp to 1e-3: where the line fitted to log "
	         "relMSE on log spp reaches 1e-3; s to 1e-3: the line fitted to seconds on spp (a fixed cost plus a cost "
	         "per sample) at that spp; ms per spp: render time / spp at the largest spp; efficiency: 1 / (relMSE x render seconds), median over the ladder.)\n";
	if (o.adaptive) {
		table += "\nAdaptive sampling, each renderer's own, at most " + std::to_string(o.adaptive_spp) +
		         " samples a pixel, over a ladder of thresholds (ours: --adaptive, the relative 95 % half-width of a "
		         "pixel's mean; Cycles: its noise threshold, minimum samples automatic). relMSE against Cycles' "
		         "reference; bias: the image's mean against the renderer's own reference, relative, mean over the " +
		         std::to_string(o.repeats) + " renders ± its standard error.\n\n"
		         "| renderer | thresholds | mean spp | relMSE | command s | render s | slope (on render s) | "
		         "s to 1e-3 (command) | s to 1e-3 (render) | efficiency (render) | bias ± standard error |\n"
		         "|---|---|---|---|---|---|---|---|---|---|---|\n";
		for (int k = 2; k < 4; k++) {
			const Curve& c = curves[k][1];
			const Curve& own = curves[k][SERIES[k].renderer == Renderer::lab ? 0 : 1];
			std::string bias;
			for (size_t i = 0; i < own.bias.size(); i++) {
				bias += (i ? " / " : "") + fmt("%+.2e ± %.1e", own.bias[i], own.bias_error[i]);
			}
			table += "| " + series_name(SERIES[k]) + " | " + joined(c.x, general) + " | " +
			         (SERIES[k].renderer == Renderer::lab ? joined(c.mean_spp, [](double v) { return fixed(v, 0); })
			                                               : std::string("not reported")) +
			         " | " + joined(c.rel_mse, general) + " | " +
			         joined(c.command_seconds, [](double v) { return fixed(v, 2); }) + " | " +
			         joined(c.render_seconds, [](double v) { return fixed(v, 2); }) + " | " + fixed(c.slope, 2) + " | " +
			         fixed(c.command_to_target, 2) + " s | " + fixed(c.render_to_target, 2) + " s | " +
			         fixed(c.efficiency, 0) + " | " + bias + " |\n";
		}
		const Curve &ours_adaptive = curves[2][1], &cycles_adaptive = curves[3][1];
		table += "\nTime to relMSE 1e-3 against Cycles' reference, render time (command): ours uniform " +
		         fixed(ours.render_to_target, 2) + " s (" + fixed(ours.command_to_target, 2) + " s), ours adaptive " +
		         fixed(ours_adaptive.render_to_target, 2) + " s (" + fixed(ours_adaptive.command_to_target, 2) +
		         " s); Cycles uniform " + fixed(cycles.render_to_target, 2) + " s (" + fixed(cycles.command_to_target, 2) +
		         " s), Cycles adaptive " + fixed(cycles_adaptive.render_to_target, 2) + " s (" +
		         fixed(cycles_adaptive.command_to_target, 2) + " s). Ours adaptive against Cycles adaptive: " +
		         fixed(ours_adaptive.render_to_target / cycles_adaptive.render_to_target, 2) + " of its render time, " +
		         fixed(ours_adaptive.command_to_target / cycles_adaptive.command_to_target, 2) +
		         " of its time from the command's start.\n";
	}
	std::printf("\n%s", table.c_str());
	std::ofstream(results_base + ".md") << table;

	Plot plot;
	plot.title = "Time to relMSE 1e-3: the lab's reference renderer beside Blender Cycles 3.4, one run";
	plot.subtitle = scene + ", max depth " + std::to_string(o.max_depth) + ", " + std::to_string(o.threads) +
	                " threads; against Cycles' " + std::to_string(o.reference_spp) + "-spp reference; load " +
	                load_ladder + " -> " + load_after;
	plot.x_label = "seconds";
	plot.columns = 2;
	for (int timing = 0; timing < 2; timing++) {
		Plot_Panel panel{timing ? "from the command's start" : "render time alone", "", {}};
		double ours_t = timing ? ours.command_to_target : ours.render_to_target;
		double cycles_t = timing ? cycles.command_to_target : cycles.render_to_target;
		panel.headline = "1e-3: ours " + fixed(ours_t, 2) + " s, Cycles " + fixed(cycles_t, 2) + " s (" +
		                 fixed(cycles_t / ours_t, 2) + "x)";
		for (size_t k = 0; k < series_count; k++) {
			const Curve& c = curves[k][1];
			panel.series.push_back({series_name(SERIES[k]), timing ? c.command_seconds : c.render_seconds, c.rel_mse, {}});
		}
		plot.panels.push_back(panel);
	}
	write_convergence_svg(results_base + ".svg", plot);
	std::printf("\nwrote %s.{md,csv,svg}\n", results_base.c_str());
	return {ours, cycles, bool(csv)};
}

// Several scenes' uniform times to relMSE 1e-3 against Cycles' reference, one row each, in markdown.
std::string scenes_summary(const Options& o, const std::vector<Scene_Result>& results, const std::string& load_before,
                           const std::string& load_after, double seconds) {
	std::string ladder;
	for (uint32_t spp : o.ladder) ladder += (ladder.empty() ? "" : ",") + std::to_string(spp);
	std::string table =
		"Time to relMSE 1e-3 against Cycles' reference, uniform sampling, ours beside Cycles, one scene after another "
		"(each scene's details in its cycles_time_to_error*.md): max depth " + std::to_string(o.max_depth) + ", " +
		std::to_string(o.threads) + " threads; " + std::to_string(o.repeats) + " renders per spp of " + ladder +
		" and renderer; references of " + std::to_string(o.reference_spp) + " spp. Load average (1, 5, 15 min) " +
		load_before + " at the start of the run, " + load_after + " at the end; the run took " + fixed(seconds, 0) +
		" s.\n\n| scene | ours s to 1e-3 (command) | Cycles s to 1e-3 (command) | ours / Cycles (command) | "
		"ours s to 1e-3 (render) | Cycles s to 1e-3 (render) | ours / Cycles (render) |\n|---|---|---|---|---|---|---|\n";
	for (size_t i = 0; i < results.size(); i++) {
		const Curve &ours = results[i].ours, &cycles = results[i].cycles;
		table += "| `" + o.scenes[i] + "` | " + fixed(ours.command_to_target, 2) + " s | " +
		         fixed(cycles.command_to_target, 2) + " s | " + fixed(ours.command_to_target / cycles.command_to_target, 2) +
		         " | " + fixed(ours.render_to_target, 2) + " s | " + fixed(cycles.render_to_target, 2) + " s | " +
		         fixed(ours.render_to_target / cycles.render_to_target, 2) + " |\n";
	}
	return table + "\n(ours / Cycles: the share of Cycles' time ours takes, e.g. 0.40: ours takes 0.40 of Cycles' time.)\n";
}

int run(const Options& o) {
	auto start = std::chrono::steady_clock::now();
	std::string load_before = load_average();
	std::vector<Scene_Result> results;
	bool written = true;
	for (const std::string& scene : o.scenes) {
		if (!results.empty()) std::printf("\n");
		results.push_back(run_scene(scene, o));
		written = written && results.back().written;
	}
	if (o.scenes.size() == 1) return written ? 0 : 1;
	double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	std::string table = scenes_summary(o, results, load_before, load_average(), seconds);
	std::printf("\n%s", table.c_str());
	std::string path = o.out + "/cycles_time_to_error_scenes.md";
	std::ofstream summary(path);
	summary << table;
	std::printf("\nwrote %s\n", path.c_str());
	return written && summary ? 0 : 1;
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

// The time-to-error benchmark: how long the reference renderer takes to bring the measured Cornell
// box (256 x 256, 2 threads, max depth 100) to relMSE 1e-3, per strategy: the lab's estimator as it
// was, each improvement alone and all of them together. (Blender Cycles beside us: cycles_bench.cpp.)
// Each strategy renders a series of spp with several seeds against one cached high-spp reference;
// a straight line fitted to log relMSE against log time gives the time to the target error. See
// README.md.
#include "bench_strategy.h"
#include "bench_timing.h"
#include "bench_usage.h"
#include "convergence_metrics.h"
#include "convergence_plot.h"
#include "convergence_reference.h"
#include "text_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace {

const char* const SCENE = "scenes/cornell_box.json";
constexpr uint32_t SIZE = 256, THREADS = 2;
const std::vector<std::string> COMMON_FLAGS{"--max-depth", "100"};
constexpr double TARGET_REL_MSE = 1e-3;
// A render whose process got less than this share of THREADS cores (CPU time / (THREADS x wall
// time)) ran on a loaded machine: its wall time says more about the others than about us.
constexpr double LOADED_BELOW = 0.9;

// The lab's estimator before issue 18, each improvement alone, and all of them.
const std::vector<Strategy> STRATEGIES{
	{"before", {"--integrator", "mixture", "--sampler", "independent", "--light-choice", "uniform"}},
	{"+ sobol", {"--integrator", "mixture", "--sampler", "sobol", "--light-choice", "uniform"}},
	{"+ nee", {"--integrator", "nee", "--sampler", "independent", "--light-choice", "uniform"}},
	{"+ power", {"--integrator", "mixture", "--sampler", "independent", "--light-choice", "power"}},
	{"all", {"--integrator", "nee", "--sampler", "sobol", "--light-choice", "power"}},
	{"adaptive", {"--integrator", "nee", "--sampler", "sobol", "--light-choice", "power"}},
};
// Adaptive sampling (framework/render/adaptive_sampling.h) on top of all: where the other series
// double the samples, its series halves the relative precision asked, threshold = ADAPTIVE_SCALE /
// sqrt(spp) at the series' level spp (a pixel whose samples' relative deviation is r takes about
// (1.96 r / threshold)^2 of them: spp / 4 where r = 1), with up to ADAPTIVE_MAX_FACTOR x spp each.
const std::string ADAPTIVE = "adaptive";
constexpr double ADAPTIVE_SCALE = 4.0;
constexpr uint32_t ADAPTIVE_MAX_FACTOR = 4;
float adaptive_threshold(double spp) {
	return float(ADAPTIVE_SCALE / std::sqrt(spp));
}
// The reference: unbiased, and with independent samples, so that its per-pixel variance estimates
// its own noise, which is subtracted from every render's relMSE (convergence_metrics.h).
const Strategy REFERENCE{"reference", {"--integrator", "nee", "--sampler", "independent", "--light-choice", "power"}};
constexpr uint64_t REFERENCE_SEED = 0; // the series use seeds 1, 2, ...

struct Options {
	std::string out = LAB_BENCH_BINARY_DIR "/time_to_error";
	std::string cache = LAB_BENCH_BINARY_DIR "/time_to_error_cache";
	uint32_t seeds = 2, min_spp = 16, max_spp = 256, reference_spp = 8192;
	std::string strategy; // empty: all
};

const Bench_Usage USAGE{"time_to_error_bench",
	"usage: time_to_error_bench [--seeds N] [--spp MIN,MAX] [--reference-spp N] [--strategy NAME] [--out DIR]\n"
	"\n"
	"Renders scenes/cornell_box.json at 256 x 256, max depth 100, on 2 threads, at spp = MIN, 2 MIN, ..., MAX\n"
	"(default 16,256; powers of two) with each strategy: --seeds renders (default 2) at MAX spp and as many\n"
	"more at smaller spp as keep the samples per point equal. relMSE is measured against a reference of\n"
	"--reference-spp samples (default 8192; cached under the build directory, delete it after changing the\n"
	"renderer). Fits log relMSE against log seconds per strategy and prints the time to relMSE 1e-3, the\n"
	"efficiency 1 / (relMSE * seconds) and its ratio to the first strategy's (Blender Cycles beside us: ./lab\n"
	"bench cycles). Times are wall times, with the CPU time beside them: a WARNING says when the machine was\n"
	"loaded.\n"
	"Writes DIR/time_to_error.csv and DIR/time_to_error.svg (default DIR: build/bench/time_to_error).\n"
	"\n"
	"strategies (--strategy NAME runs one, with \"before\"):\n"
	"  before        the lab's estimator before issue 18: task 6's mixture, independent samples, lights chosen\n"
	"                uniformly\n"
	"  + sobol       low-discrepancy samples      + nee    next-event estimation with MIS\n"
	"  + power       lights chosen by power\n"
	"  all           all of them (the reference renderer's defaults)\n"
	"  adaptive      all, with adaptive sampling (--adaptive): its series halves the threshold, 4 / sqrt(spp),\n"
	"                up to 4 spp a pixel; the image mean's bias against the reference is printed beside all's\n"};

uint32_t power_of_two(const std::string& option, const std::string& text) {
	uint32_t value = USAGE.whole_number(option, text, 1);
	if (value & (value - 1)) USAGE.error(option + " needs powers of two, got '" + text + "'");
	return value;
}

Options parse(int argc, char** argv) {
	Options o;
	for (int i = 1; i < argc; i++) {
		std::string arg = argv[i];
		USAGE.help_if_asked(arg);
		std::string value = USAGE.value_of(i, argc, argv);
		if (arg == "--out") o.out = value;
		else if (arg == "--seeds") o.seeds = USAGE.whole_number(arg, value, 1);
		else if (arg == "--reference-spp") o.reference_spp = USAGE.whole_number(arg, value, 1);
		else if (arg == "--strategy") o.strategy = value;
		else if (arg == "--spp") {
			size_t comma = value.find(',');
			if (comma == std::string::npos) USAGE.error("--spp needs MIN,MAX, e.g. 16,256, got '" + value + "'");
			o.min_spp = power_of_two(arg, value.substr(0, comma));
			o.max_spp = power_of_two(arg, value.substr(comma + 1));
		} else USAGE.error("unknown option '" + arg + "'");
	}
	if (o.max_spp < 2 * o.min_spp) USAGE.error("--spp: MAX must be at least twice MIN (a series needs two points)");
	return o;
}

double mean(const std::vector<double>& values) {
	double sum = 0.0;
	for (double v : values) sum += v;
	return sum / double(values.size());
}

// "0.22 0.28 0.29": the 1, 5 and 15 minute load averages.
std::string load_average() {
	std::ifstream file("/proc/loadavg");
	std::string one, five, fifteen;
	file >> one >> five >> fifteen;
	return file ? one + " " + five + " " + fifteen : "unknown";
}

// ---- One strategy's series ----------------------------------------------------------------------

struct Render_Result {
	uint32_t spp;
	uint64_t seed;
	double seconds, cpu_seconds, rel_mse;
	double bias; // (the image's mean luminance - the reference's) / the reference's
};

// The relative difference of the film's mean luminance over the image from the reference's.
double image_bias(const Film& film, const Reference& reference) {
	double ours = 0.0, theirs = 0.0;
	for (size_t i = 0; i < film.pixels.size(); i++) {
		ours += double(luminance(film.pixels[i].mean_value()));
		theirs += double(luminance(reference.mean.pixels[i]));
	}
	return (ours - theirs) / theirs;
}

struct Curve {
	std::vector<double> spp, seconds, cpu_seconds, rel_mse; // per level: medians of time, mean relMSE
	double slope_spp = 0, slope_time = 0;
	double time_to_target = 0, cpu_time_to_target = 0; // from the fitted lines
	double efficiency = 0, cpu_efficiency = 0;          // median over the levels of 1 / (relMSE * time)
	double cpu_share = 0;                               // median over the renders
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

Curve fit(const std::vector<Render_Result>& renders, double reference_share) {
	Curve c;
	std::vector<double> shares;
	for (uint32_t spp = 0;;) {
		// The next level: the smallest spp above `spp`.
		uint32_t next = UINT32_MAX;
		for (const Render_Result& r : renders)
			if (r.spp > spp) next = std::min(next, r.spp);
		if (next == UINT32_MAX) break;
		spp = next;
		std::vector<double> seconds, cpu, errors;
		for (const Render_Result& r : renders) {
			if (r.spp != spp) continue;
			seconds.push_back(r.seconds);
			cpu.push_back(r.cpu_seconds);
			errors.push_back(r.rel_mse);
			shares.push_back(r.cpu_seconds / (THREADS * r.seconds));
		}
		c.spp.push_back(spp);
		c.seconds.push_back(median(seconds));
		c.cpu_seconds.push_back(median(cpu));
		c.rel_mse.push_back(mean(errors) - reference_share);
	}
	c.slope_spp = log_log_slope(c.spp, c.rel_mse);
	c.slope_time = log_log_slope(c.seconds, c.rel_mse);
	c.time_to_target = fitted_x_at(c.seconds, c.rel_mse, TARGET_REL_MSE);
	c.cpu_time_to_target = fitted_x_at(c.cpu_seconds, c.rel_mse, TARGET_REL_MSE);
	std::vector<double> efficiency, cpu_efficiency;
	for (size_t i = 0; i < c.spp.size(); i++) {
		efficiency.push_back(1.0 / (c.rel_mse[i] * c.seconds[i]));
		cpu_efficiency.push_back(1.0 / (c.rel_mse[i] * c.cpu_seconds[i] / THREADS));
	}
	c.efficiency = median(efficiency);
	c.cpu_efficiency = median(cpu_efficiency);
	c.cpu_share = median(shares);
	return c;
}

// ---- The run ------------------------------------------------------------------------------------

Strategy with_common_flags(const Strategy& s) {
	Strategy full = s;
	full.flags.insert(full.flags.end(), COMMON_FLAGS.begin(), COMMON_FLAGS.end());
	return full;
}

Reference reference_image(const Options& o) {
	Strategy reference = with_common_flags(REFERENCE);
	Strategy_Setup setup = set_up(SCENE, reference, SIZE, SIZE);
	Render_Settings settings = setup.settings;
	settings.samples = o.reference_spp;
	settings.seed = REFERENCE_SEED;
	std::string identity = read_text_file(SCENE) + "|" + joined(reference.flags);
	Cached_Reference cached = cached_reference(Pathtracer(*setup.scene, settings, View::path, setup.estimator), identity, o.cache, THREADS);
	if (cached.from_cache)
		std::printf("reference: %u spp, from the cache %s (delete it after changing the renderer)\n", o.reference_spp,
		            cached.path.c_str());
	else
		std::printf("reference: %u spp, rendered in %.0f s, cached in %s\n", o.reference_spp, cached.seconds,
		            cached.path.c_str());
	return cached.reference;
}

int run(const Options& o) {
	std::vector<Strategy> chosen;
	for (const Strategy& s : STRATEGIES)
		if (o.strategy.empty() || s.name == o.strategy || &s == &STRATEGIES.front()) chosen.push_back(with_common_flags(s));
	if (chosen.size() < 2 && !o.strategy.empty()) USAGE.error("unknown strategy '" + o.strategy + "'");

	std::printf("time to relMSE %g: %s, %u x %u, max depth 100, %u threads; load average at the start: %s\n",
	            TARGET_REL_MSE, SCENE, SIZE, SIZE, THREADS, load_average().c_str());
	Reference reference = reference_image(o);
	double share = reference_rel_mse(reference);
	std::printf("the reference's own noise adds %.3g to every relMSE; it is subtracted before fitting\n", share);

	std::vector<Strategy_Setup> setups;
	for (const Strategy& s : chosen) setups.push_back(set_up(SCENE, s, SIZE, SIZE));
	for (const Strategy_Setup& setup : setups) timed_render(setup, 1, 0, THREADS); // warm-up, not timed

	// Every render of a series, shuffled (fixed): a change in the load spreads over all spp. The
	// strategies take turns at each render, so that they share the load.
	struct Job {
		uint32_t spp;
		uint64_t seed;
	};
	std::vector<Job> jobs;
	uint64_t seed = REFERENCE_SEED + 1;
	for (uint32_t spp = o.min_spp; spp <= o.max_spp; spp *= 2)
		for (uint32_t i = 0; i < o.seeds * (o.max_spp / spp); i++) jobs.push_back({spp, seed++});
	std::shuffle(jobs.begin(), jobs.end(), std::mt19937(12345));

	std::filesystem::create_directories(o.out);
	std::string csv_path = o.out + "/time_to_error.csv", svg_path = o.out + "/time_to_error.svg";
	std::ofstream csv(csv_path);
	csv << "strategy,flags,spp,seed,seconds,cpu_seconds,relmse,reference_relmse\n";
	std::vector<std::vector<Render_Result>> results(chosen.size());
	std::printf("rendering %zu images per strategy (%u to %u spp), in a shuffled order...", jobs.size(), o.min_spp,
	            o.max_spp);
	std::fflush(stdout);
	auto start = std::chrono::steady_clock::now();
	for (const Job& job : jobs) {
		for (size_t k = 0; k < chosen.size(); k++) {
			bool adaptive = chosen[k].name == ADAPTIVE;
			Timed_Render render =
				adaptive ? timed_render(setups[k], ADAPTIVE_MAX_FACTOR * job.spp, job.seed, THREADS,
				                        adaptive_threshold(job.spp))
				         : timed_render(setups[k], job.spp, job.seed, THREADS);
			Render_Result r{job.spp, job.seed, render.seconds, render.cpu_seconds,
			                render_error(render.film, reference).rel_mse, image_bias(render.film, reference)};
			results[k].push_back(r);
			char line[512];
			std::snprintf(line, sizeof line, "%s,%s,%u,%llu,%.6g,%.6g,%.6g,%.6g\n", chosen[k].name.c_str(),
			              joined(chosen[k].flags).c_str(), r.spp, static_cast<unsigned long long>(r.seed), r.seconds,
			              r.cpu_seconds, r.rel_mse, share);
			csv << line;
		}
	}
	std::printf(" %.0f s; load average at the end: %s\n",
	            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), load_average().c_str());

	std::vector<Curve> curves;
	for (const auto& r : results) curves.push_back(fit(r, share));
	const Curve& before = curves.front();

	std::printf("\n%-13s %9s %9s  %-26s %8s %8s %9s %9s %7s %6s\n", "strategy", "slope/spp", "slope/s",
	            "relMSE at each spp", "to 1e-3", "CPU/2", "efficiency", "eff. CPU", "ratio", "CPU %");
	for (size_t k = 0; k < curves.size(); k++) {
		const Curve& c = curves[k];
		std::string errors;
		for (size_t i = 0; i < c.rel_mse.size(); i += 2) {
			char e[24];
			std::snprintf(e, sizeof e, "%s%.3g", errors.empty() ? "" : " ", c.rel_mse[i]);
			errors += e;
		}
		std::printf("%-13s %9.3f %9.3f  %-26s %7.2fs %7.2fs %9.1f %9.1f %6.2fx %5.0f%%\n", chosen[k].name.c_str(),
		            c.slope_spp, c.slope_time, errors.c_str(), c.time_to_target, c.cpu_time_to_target / THREADS,
		            c.efficiency, c.cpu_efficiency, c.efficiency / before.efficiency, 100 * c.cpu_share);
	}
	std::printf("(relMSE at spp");
	for (size_t i = 0; i < before.spp.size(); i += 2) std::printf(" %g", before.spp[i]);
	std::printf(", mean over the renders minus the reference's share; to 1e-3: wall seconds from the line fitted to\n"
	            " log relMSE on log seconds, and CPU seconds / %u from the same fit on CPU time, the wall time an idle\n"
	            " machine would take; efficiency 1 / (relMSE * seconds), median over the series; ratio: efficiency /\n"
	            " the first strategy's; CPU %%: CPU time / (%u x wall time))\n",
	            THREADS, THREADS);

	// The bias of the image's mean, at each level: the mean over its renders, with its standard error.
	std::printf("\nbias of the image's mean luminance against the reference, (ours - reference) / reference, mean "
	            "+- standard error over the renders of each level (spp; adaptive: its threshold):\n");
	for (size_t k = 0; k < chosen.size(); k++) {
		if (chosen[k].name != ADAPTIVE && chosen[k].name != "all") continue;
		std::printf("  %-9s", chosen[k].name.c_str());
		for (double level : curves[k].spp) {
			std::vector<double> biases;
			for (const Render_Result& r : results[k])
				if (r.spp == level) biases.push_back(r.bias);
			double m = mean(biases), sum = 0.0;
			for (double b : biases) sum += (b - m) * (b - m);
			double error = biases.size() > 1 ? std::sqrt(sum / double(biases.size() - 1) / double(biases.size())) : 0.0;
			if (chosen[k].name == ADAPTIVE)
				std::printf("  %.3g: %+.2e +- %.1e", adaptive_threshold(level), m, error);
			else
				std::printf("  %g: %+.2e +- %.1e", level, m, error);
		}
		std::printf("\n");
	}

	int status = 0;
	double lowest_share = 1.0;
	for (const Curve& c : curves) lowest_share = std::min(lowest_share, c.cpu_share);
	if (lowest_share < LOADED_BELOW) {
		std::printf("WARNING: the machine was loaded: a strategy's renders got %.0f%% of %u cores (median); its wall "
		            "times, and the ratios between strategies, move with the load. The CPU columns are steadier; "
		            "rerun when `uptime` shows a load below 0.5.\n",
		            100 * lowest_share, THREADS);
	}
	for (size_t k = 0; k < curves.size(); k++) {
		// Adaptive sampling's series is not one of spp (its threshold halves), and its bias puts a floor
		// under its relMSE: its slope is printed, not checked.
		if (chosen[k].name == ADAPTIVE) continue;
		if (curves[k].slope_spp < -1.3 || curves[k].slope_spp > -0.8) {
			std::printf("ERROR: %s: slope %.3f against spp is outside [-1.3, -0.8]\n", chosen[k].name.c_str(),
			            curves[k].slope_spp);
			status = 1;
		}
	}

	Plot plot;
	plot.title = "Time to relMSE 1e-3 on the Cornell box, per strategy";
	plot.subtitle = "256 x 256, max depth 100, 2 threads; wall time of each render, median per point";
	plot.x_label = "render time [s]";
	Plot_Panel panel{"each improvement alone, and all together", "", {}};
	char headline[128];
	std::snprintf(headline, sizeof headline, "%s: relMSE 1e-3 in %.1f s, %.2fx the efficiency of before",
	              chosen.back().name.c_str(), curves.back().time_to_target, curves.back().efficiency / before.efficiency);
	panel.headline = headline;
	for (size_t k = 0; k < curves.size(); k++) {
		char label[128];
		std::snprintf(label, sizeof label, "%s: 1e-3 in %.1f s (%.2fx)", chosen[k].name.c_str(), curves[k].time_to_target,
		              curves[k].efficiency / before.efficiency);
		panel.series.push_back({label, curves[k].seconds, curves[k].rel_mse, {}});
	}
	plot.panels.push_back(panel);
	write_convergence_svg(svg_path, plot);
	std::printf("\nwrote %s\nwrote %s\n", csv_path.c_str(), svg_path.c_str());
	if (!csv) std::printf("ERROR: could not write %s\n", csv_path.c_str());
	return csv && status == 0 ? 0 : 1;
}

} // namespace

int main(int argc, char** argv) {
	try {
		return run(parse(argc, argv));
	} catch (const std::exception& e) {
		std::fprintf(stderr, "error: %s\n", e.what());
		return 2;
	}
}

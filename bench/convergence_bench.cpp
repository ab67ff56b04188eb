// The convergence benchmark, "run time against error": for each experiment (a scene and two
// strategies of the renderer that estimate the same image) it renders at spp = 1, 2, 4, ..., max
// with several seeds, measures the wall time and the relMSE against a high-spp reference, fits the
// slope of log relMSE against log spp (-1 for an unbiased estimator with independent samples) and
// against log time, and compares the strategies' efficiency 1 / (relMSE * time). Writes a CSV of
// every render and an SVG plot. See README.md.
#include "bench_strategy.h"
#include "bench_timing.h"
#include "bench_usage.h"
#include "convergence_metrics.h"
#include "convergence_plot.h"
#include "convergence_reference.h"
#include "text_file.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
	return std::chrono::duration<double>(Clock::now() - start).count();
}

// ---- The experiments ----------------------------------------------------------------------------

// Two unbiased strategies for the same image: a baseline and an improvement. The reference is
// rendered by the improvement with independent samples (its per-pixel variance then measures its
// own noise, which is subtracted), with REFERENCE_FACTOR times the largest spp.
struct Experiment {
	const char* name;
	const char* scene;
	const char* compared; // the plot's panel title: what is compared
	Strategy baseline, improved;
};

// The lab's estimator before issue 18 (task 4 with task 6's mixture, independent samples, lights
// chosen uniformly), which the first three experiments vary.
std::vector<std::string> lab(std::vector<std::string> flags) {
	std::vector<std::string> all{"--integrator", "mixture", "--sampler", "independent", "--light-choice", "uniform"};
	all.insert(all.end(), flags.begin(), flags.end());
	return all;
}

// NEE with independent samples, lights chosen as `how` says.
std::vector<std::string> nee_choosing(const char* how) {
	return {"--integrator", "nee", "--sampler", "independent", "--light-choice", how};
}

const std::vector<Experiment> EXPERIMENTS{
	{"small_light", "scenes/cornell_small_light.json", "small light: BSDF sampling vs task 6's mixture",
	 {"bsdf only", lab({"--no-light-sampling"})}, {"mixture", lab({})}},
	{"sun", "scenes/bunny_sun.json", "sun: sky sampled uniformly vs by importance",
	 {"uniform env", lab({"--env-sampling", "uniform"})}, {"importance env", lab({"--env-sampling", "importance"})}},
	{"roulette", "bench/convergence_closed_box.json", "closed box: every path to depth 16 vs roulette",
	 {"no roulette", lab({"--no-roulette"})}, {"roulette", lab({})}},
	{"integrator", "scenes/cornell_box.json", "Cornell box: task 6's mixture vs NEE with MIS",
	 {"mixture", {"--integrator", "mixture", "--sampler", "independent"}},
	 {"nee + mis", {"--integrator", "nee", "--sampler", "independent"}}},
	{"sampler", "scenes/cornell_box.json", "Cornell box: independent vs low-discrepancy samples",
	 {"independent", {"--integrator", "nee", "--sampler", "independent"}},
	 {"sobol", {"--integrator", "nee", "--sampler", "sobol"}}},
	{"light_choice", "bench/convergence_two_lights.json", "bright and dim light: chosen uniformly vs by power",
	 {"uniform", {"--integrator", "nee", "--sampler", "independent", "--light-choice", "uniform"}},
	 {"power", {"--integrator", "nee", "--sampler", "independent", "--light-choice", "power"}}},
	{"light_choice_sky", "scenes/dragon.json", "lamp under a sky: chosen uniformly vs by power",
	 {"uniform", {"--integrator", "nee", "--sampler", "independent", "--light-choice", "uniform"}},
	 {"power", {"--integrator", "nee", "--sampler", "independent", "--light-choice", "power"}}},
	// The light tree (issue 26) against the choice each scene had before: by power (and uniform
	// where power loses).
	{"tree_many", "scenes/many_lights.json", "120 lamps: chosen by power vs the light tree",
	 {"power", nee_choosing("power")}, {"tree", nee_choosing("tree")}},
	{"tree_many_uniform", "scenes/many_lights.json", "120 lamps: chosen uniformly vs the light tree",
	 {"uniform", nee_choosing("uniform")}, {"tree", nee_choosing("tree")}},
	{"tree_sky", "scenes/dragon.json", "lamp under a sky: chosen uniformly vs the light tree",
	 {"uniform", nee_choosing("uniform")}, {"tree", nee_choosing("tree")}},
	{"tree_sky_power", "scenes/dragon.json", "lamp under a sky: chosen by power vs the light tree",
	 {"power", nee_choosing("power")}, {"tree", nee_choosing("tree")}},
	{"tree_overcast", "scenes/dragon_overcast.json", "lamp under an HDR sky: by power vs the light tree",
	 {"power", nee_choosing("power")}, {"tree", nee_choosing("tree")}},
	{"tree_one_light", "scenes/cornell_box.json", "one light: by power vs the light tree (the same choices)",
	 {"power", nee_choosing("power")}, {"tree", nee_choosing("tree")}},
};

constexpr uint32_t REFERENCE_FACTOR = 64;
constexpr uint64_t REFERENCE_SEED = 0; // the series use seeds 1, 2, ...: independent of it
// The slope of log relMSE against log spp: -1 for independent samples; low-discrepancy samples
// may fall faster.
constexpr double SLOPE_MIN = -1.3, SLOPE_MAX = -0.8;

// ---- Options ------------------------------------------------------------------------------------

struct Options {
	std::string out = LAB_BENCH_BINARY_DIR "/convergence";
	std::string cache = LAB_BENCH_BINARY_DIR "/convergence_cache";
	uint32_t seeds = 8, max_spp = 64, width = 64, height = 64, threads = 0;
	std::string experiment; // empty: all
};

const Bench_Usage USAGE{"convergence_bench",
	"usage: convergence_bench [--out DIR] [--seeds N] [--max-spp N] [--size WxH] [--threads T] [--experiment NAME[,NAME...]]\n"
	"\n"
	"Renders each experiment's two strategies at spp = 1, 2, 4, ..., N (default 64; a power of two) on a WxH\n"
	"film (default 64x64) with T threads (default 0 = all cores): --seeds renders (default 8) at N spp, and as\n"
	"many more at smaller spp as keep the samples per point equal (8 x 64 renders at 1 spp). Measures wall time\n"
	"and relMSE against a reference of 64 x N spp (cached under the build directory). Prints per strategy the\n"
	"slopes of log relMSE against log spp and log time, and the efficiency 1 / (relMSE * time); writes\n"
	"DIR/convergence.csv and DIR/convergence.svg (default DIR: build/bench/convergence). A slope against spp\n"
	"outside [-1.3, -0.8] is an ERROR (exit status 1) unless a few renders carry the means (a heavy tail): a\n"
	"WARNING (see bench/README.md). Slopes against time move with the machine's load: reported, not judged.\n"
	"Budgets much smaller than the defaults may not see a heavy tail's rare paths at all, and its curve then\n"
	"looks biased.\n"
	"\n"
	"experiments (--experiment NAME,... runs those; each strategy is a list of pathtracer_reference's flags):\n"
	"  small_light       cornell_small_light: bsdf only (--no-light-sampling) vs task 6's mixture\n"
	"  sun               bunny_sun: uniform env vs importance env (--env-sampling uniform|importance)\n"
	"  roulette          bench/convergence_closed_box.json: no roulette (--no-roulette) vs roulette\n"
	"  integrator        cornell_box: --integrator mixture vs nee\n"
	"  sampler           cornell_box: --sampler independent vs sobol\n"
	"  light_choice      bench/convergence_two_lights.json: --light-choice uniform vs power\n"
	"  light_choice_sky  dragon (a lamp under a sky): --light-choice uniform vs power\n"
	"  tree_many         many_lights (120 lamps): --light-choice power vs tree\n"
	"  tree_many_uniform many_lights: --light-choice uniform vs tree\n"
	"  tree_sky          dragon: --light-choice uniform vs tree\n"
	"  tree_sky_power    dragon: --light-choice power vs tree\n"
	"  tree_overcast     dragon_overcast (a lamp under an HDR sky): --light-choice power vs tree\n"
	"  tree_one_light    cornell_box (one light: the same choices): --light-choice power vs tree\n"};

Options parse(int argc, char** argv) {
	Options o;
	for (int i = 1; i < argc; i++) {
		std::string arg = argv[i];
		USAGE.help_if_asked(arg);
		std::string value = USAGE.value_of(i, argc, argv);
		if (arg == "--out") o.out = value;
		else if (arg == "--seeds") o.seeds = USAGE.whole_number(arg, value, 1);
		else if (arg == "--max-spp") o.max_spp = USAGE.whole_number(arg, value, 1);
		else if (arg == "--threads") o.threads = USAGE.whole_number(arg, value, 0);
		else if (arg == "--experiment") o.experiment = value;
		else if (arg == "--size") {
			if (std::sscanf(value.c_str(), "%ux%u", &o.width, &o.height) != 2 || o.width < 1 || o.height < 1)
				USAGE.error("--size needs WxH, e.g. 64x64, got '" + value + "'");
		} else USAGE.error("unknown option '" + arg + "'");
	}
	if (o.max_spp < 2) USAGE.error("--max-spp must be at least 2 (a series needs two points)");
	while (o.max_spp & (o.max_spp - 1)) o.max_spp &= o.max_spp - 1; // the series: powers of two
	return o;
}

// The number of renders (seeds) at `spp`: --seeds at the largest spp of the series, and as many
// more at smaller spp as keep the samples per point equal. Rare, bright paths (a small light found
// by BSDF sampling, the sun by uniform sampling) dominate the mean relMSE; with equal samples, each
// point's mean includes as many of them, and is as trustworthy as the next.
uint32_t renders_at(uint32_t spp, const Options& o) {
	return o.seeds * (o.max_spp / spp);
}

// Every render of a series: spp 1, 2, 4, ..., max (level 0, 1, 2, ...), renders_at(spp) of each,
// each with a seed of its own, in a shuffled order (fixed): a change in the machine's load then
// spreads over all spp instead of bending the curve.
struct Render_Job {
	size_t level;
	uint32_t spp;
	uint64_t seed;
};

std::vector<Render_Job> render_jobs(const Options& o) {
	std::vector<Render_Job> jobs;
	uint64_t seed = REFERENCE_SEED + 1;
	for (size_t level = 0; (1u << level) <= o.max_spp; level++)
		for (uint32_t i = 0; i < renders_at(1u << level, o); i++) jobs.push_back({level, 1u << level, seed++});
	std::shuffle(jobs.begin(), jobs.end(), std::mt19937(12345));
	return jobs;
}

// ---- Rendering ----------------------------------------------------------------------------------

struct Measurement {
	double seconds = 0.0; // wall time of render()
	Render_Error error;
};

Measurement measure(const Strategy_Setup& setup, uint32_t spp, uint64_t seed, const Reference& reference,
                    uint32_t threads) {
	Timed_Render render = timed_render(setup, spp, seed, threads);
	return Measurement{render.seconds, render_error(render.film, reference)};
}

// ---- Results ------------------------------------------------------------------------------------

// One strategy's series: per spp, the median time over the renders and the mean relMSE over the
// renders minus the reference's share (reference_rel_mse).
struct Curve {
	std::vector<double> spp, seconds, rel_mse;
	std::vector<double> skew; // per spp: the mean relMSE of the renders over their median
	double slope_time = 0.0, slope_spp = 0.0;
	double efficiency = 0.0; // median over the series of 1 / (relMSE * seconds)

	// Rare, bright paths (fireflies) carry a mean: it is more than twice the median render's error.
	// (A render's relMSE averages thousands of pixel channels: without them, mean and median agree.)
	// The mean then depends on how many of those renders happened, and so does the slope.
	static bool carried_by_few(double skew) {
		return skew > 2.0;
	}
	bool heavy_tailed() const {
		return std::any_of(skew.begin(), skew.end(), carried_by_few);
	}
	bool slope_ok() const {
		return slope_spp >= SLOPE_MIN && slope_spp <= SLOPE_MAX;
	}
};

struct Result {
	const Experiment* experiment;
	Curve curves[2]; // baseline, improved
	double reference_share = 0.0;
};

double mean(const std::vector<double>& values) {
	double sum = 0.0;
	for (double v : values) sum += v;
	return sum / double(values.size());
}

void add_point(Curve& curve, uint32_t spp, const std::vector<Measurement>& seeds, double reference_share) {
	std::vector<double> seconds, rel_mse;
	for (const Measurement& m : seeds) {
		seconds.push_back(m.seconds);
		rel_mse.push_back(m.error.rel_mse);
	}
	curve.spp.push_back(spp);
	curve.seconds.push_back(median(seconds));
	curve.rel_mse.push_back(mean(rel_mse) - reference_share);
	curve.skew.push_back(mean(rel_mse) / median(rel_mse));
}

void fit(Curve& curve) {
	curve.slope_time = log_log_slope(curve.seconds, curve.rel_mse);
	curve.slope_spp = log_log_slope(curve.spp, curve.rel_mse);
	std::vector<double> efficiencies;
	for (size_t i = 0; i < curve.spp.size(); i++) efficiencies.push_back(1.0 / (curve.rel_mse[i] * curve.seconds[i]));
	curve.efficiency = median(efficiencies);
}

// One line per render.
class Csv {
public:
	explicit Csv(const std::string& path) : file(path) {
		file << "experiment,strategy,scene,spp,seed,seconds,relmse,variance,reference_relmse\n";
	}
	void row(const Experiment& e, const Strategy& s, uint32_t spp, uint64_t seed, const Measurement& m, double share) {
		char line[512];
		std::snprintf(line, sizeof line, "%s,%s,%s,%u,%llu,%.6g,%.6g,%.6g,%.6g\n", e.name, s.name.c_str(), e.scene, spp,
		              static_cast<unsigned long long>(seed), m.seconds, m.error.rel_mse, m.error.variance, share);
		file << line;
	}
	bool good() const {
		return bool(file);
	}

private:
	std::ofstream file;
};

// ---- The experiment -----------------------------------------------------------------------------

Cached_Reference reference_for(const Experiment& e, const Options& o) {
	Strategy strategy = e.improved;
	strategy.flags.insert(strategy.flags.end(), {"--sampler", "independent"}); // the last flag counts
	Strategy_Setup setup = set_up(e.scene, strategy, o.width, o.height);
	Render_Settings settings = setup.settings;
	settings.samples = REFERENCE_FACTOR * o.max_spp;
	settings.seed = REFERENCE_SEED;
	std::string identity = read_text_file(e.scene) + "|" + joined(strategy.flags);
	Cached_Reference cached = cached_reference(Pathtracer(*setup.scene, settings, View::path, setup.estimator), identity, o.cache, o.threads);
	if (cached.from_cache)
		std::printf("reference: %u spp by \"%s\", independent samples, from the cache %s (delete it after changing the "
		            "renderer)\n",
		            settings.samples, e.improved.name.c_str(), cached.path.c_str());
	else
		std::printf("reference: %u spp by \"%s\", independent samples, rendered in %.1f s, cached in %s\n",
		            settings.samples, e.improved.name.c_str(), cached.seconds, cached.path.c_str());
	return cached;
}

Result run_experiment(const Experiment& e, const Options& o, Csv& csv) {
	std::printf("\n== %s: %s, %u x %u, spp 1 to %u; %u renders at %u spp to %u at 1 spp ==\n", e.name, e.scene,
	            o.width, o.height, o.max_spp, o.seeds, o.max_spp, renders_at(1, o));
	const Strategy* strategies[2] = {&e.baseline, &e.improved};
	Strategy_Setup setups[2] = {set_up(e.scene, e.baseline, o.width, o.height),
	                            set_up(e.scene, e.improved, o.width, o.height)};
	Reference reference = reference_for(e, o).reference;
	Result result{&e, {}, reference_rel_mse(reference)};
	std::printf("the reference's own noise adds %.3g to every relMSE; it is subtracted before fitting\n",
	            result.reference_share);

	for (const Strategy_Setup& setup : setups) measure(setup, 1, 0, reference, o.threads); // warm-up, not timed
	std::vector<std::vector<Measurement>> runs[2]; // [strategy][level of the series]
	std::vector<Render_Job> jobs = render_jobs(o);
	std::printf("rendering %zu images per strategy, in a shuffled order...", jobs.size());
	std::fflush(stdout);
	Clock::time_point start = Clock::now();
	for (const Render_Job& job : jobs) {
		for (int k = 0; k < 2; k++) { // the strategies take turns: the same load for both
			runs[k].resize(std::max(runs[k].size(), job.level + 1));
			runs[k][job.level].push_back(measure(setups[k], job.spp, job.seed, reference, o.threads));
			csv.row(e, *strategies[k], job.spp, job.seed, runs[k][job.level].back(), result.reference_share);
		}
	}

	std::printf(" %.0f s\n%6s", seconds_since(start), "spp");
	for (const Strategy* s : strategies) std::printf("   %16s: seconds   relMSE", s->name.c_str());
	std::printf("\n");
	for (size_t level = 0; level < runs[0].size(); level++) {
		uint32_t spp = 1u << level;
		std::printf("%6u", spp);
		for (int k = 0; k < 2; k++) {
			Curve& c = result.curves[k];
			add_point(c, spp, runs[k][level], result.reference_share);
			std::printf("   %16s  %8.4f  %8.3g%s", "", c.seconds.back(), c.rel_mse.back(),
			            Curve::carried_by_few(c.skew.back()) ? "*" : " ");
		}
		std::printf("\n");
	}
	std::printf("(seconds: median over the renders; relMSE: their mean; *: more than twice their median)\n");
	for (Curve& curve : result.curves) fit(curve);
	return result;
}

// ---- Report -------------------------------------------------------------------------------------

// An unbiased estimator's relMSE falls as 1 / spp with independent samples (low-discrepancy samples
// may fall faster). A slope against spp outside [SLOPE_MIN, SLOPE_MAX] is an ERROR unless a few
// renders carry the mean of some point ("heavy tail": rare, bright paths that the series has too
// few samples to average, so the slope cannot be judged at this budget). Bias shows differently:
// the renders agree with each other, and the curve flattens. A heavy tail is worth knowing about
// even when the slope passes: "ok, heavy tail". Slopes against time follow the machine's load and
// are only reported.
const char* verdict(const Curve& c) {
	if (c.slope_ok()) return c.heavy_tailed() ? "ok, heavy tail" : "ok";
	return c.heavy_tailed() ? "heavy tail" : "ERROR";
}

double ratio(const Result& r) {
	return r.curves[1].efficiency / r.curves[0].efficiency;
}

void print_table(const std::vector<Result>& results) {
	std::printf("\n%-17s %-15s %-62s %9s %10s %11s %8s  %s\n", "experiment", "strategy", "renderer flags",
	            "slope/spp", "slope/time", "efficiency", "ratio", "slope");
	for (const Result& r : results) {
		const Strategy* strategies[2] = {&r.experiment->baseline, &r.experiment->improved};
		for (int k = 0; k < 2; k++) {
			const Curve& c = r.curves[k];
			char gain[32] = "";
			if (k == 1) std::snprintf(gain, sizeof gain, "%.3gx", ratio(r));
			std::printf("%-17s %-15s %-62s %9.3f %10.3f %11.4g %8s  %s\n", k == 0 ? r.experiment->name : "",
			            strategies[k]->name.c_str(), joined(strategies[k]->flags).c_str(), c.slope_spp, c.slope_time,
			            c.efficiency, gain, verdict(c));
		}
	}
	std::printf("(slopes: least squares of log relMSE on log spp and on log seconds; efficiency: median over the\n"
	            " series of 1 / (relMSE * seconds) in 1/s; ratio: efficiency of the second strategy / the first)\n");
}

// Prints a WARNING or an ERROR for every slope outside the range (see verdict()); false on an ERROR.
bool check_slopes(const std::vector<Result>& results) {
	bool ok = true;
	for (const Result& r : results) {
		const Strategy* strategies[2] = {&r.experiment->baseline, &r.experiment->improved};
		for (int k = 0; k < 2; k++) {
			const Curve& c = r.curves[k];
			if (c.slope_ok()) continue;
			bool error = std::string(verdict(c)) == "ERROR";
			const char* why = error ? "the renders agree, yet the error does not fall as 1 / spp: look for bias"
			                        : "a few renders carry its means (rare bright paths: a heavy tail); more samples "
			                          "per point would tell whether it converges";
			std::printf("%s: %s / %s: slope %.3f against spp is outside [%.1f, %.1f]: %s\n", error ? "ERROR" : "WARNING",
			            r.experiment->name, strategies[k]->name.c_str(), c.slope_spp, SLOPE_MIN, SLOPE_MAX, why);
			ok = ok && !error;
		}
	}
	return ok;
}

Plot convergence_plot(const std::vector<Result>& results, const Options& o) {
	Plot plot;
	plot.title = "Run time against error: relMSE against samples per pixel, two strategies per panel";
	char subtitle[256];
	std::snprintf(subtitle, sizeof subtitle,
	              "%u x %u pixels, spp 1 to %u, %u x %u samples per point; %s threads; efficiency = 1 / (relMSE x "
	              "wall time of the render), median over the series",
	              o.width, o.height, o.max_spp, o.seeds, o.max_spp,
	              o.threads ? std::to_string(o.threads).c_str() : std::to_string(std::thread::hardware_concurrency()).c_str());
	plot.subtitle = subtitle;
	for (const Result& r : results) {
		const Experiment& e = *r.experiment;
		char headline[128];
		std::snprintf(headline, sizeof headline, "%s: %.3gx the efficiency of %s", e.improved.name.c_str(), ratio(r),
		              e.baseline.name.c_str());
		Plot_Panel panel{e.compared, headline, {}};
		const Strategy* strategies[2] = {&e.baseline, &e.improved};
		for (int k = 0; k < 2; k++) {
			const Curve& c = r.curves[k];
			char label[96];
			std::snprintf(label, sizeof label, "%s: slope %.2f", strategies[k]->name.c_str(), c.slope_spp);
			std::vector<bool> hollow;
			for (double skew : c.skew) hollow.push_back(Curve::carried_by_few(skew));
			panel.series.push_back({label, c.spp, c.rel_mse, hollow});
		}
		plot.panels.push_back(panel);
	}
	return plot;
}

int run(const Options& o) {
	// --experiment A,B,C: those, in the table's order.
	std::vector<std::string> names;
	for (size_t begin = 0; begin < o.experiment.size();) {
		size_t comma = std::min(o.experiment.find(',', begin), o.experiment.size());
		names.push_back(o.experiment.substr(begin, comma - begin));
		begin = comma + 1;
	}
	std::vector<const Experiment*> chosen;
	for (const Experiment& e : EXPERIMENTS)
		if (names.empty() || std::find(names.begin(), names.end(), e.name) != names.end()) chosen.push_back(&e);
	for (const std::string& name : names) {
		auto named = [&](const Experiment* e) { return name == e->name; };
		if (std::none_of(chosen.begin(), chosen.end(), named)) USAGE.error("unknown experiment '" + name + "'");
	}

	Clock::time_point start = Clock::now();
	std::string csv_path = o.out + "/convergence.csv", svg_path = o.out + "/convergence.svg";
	std::filesystem::create_directories(o.out);
	Csv csv(csv_path);
	std::vector<Result> results;
	for (const Experiment* e : chosen) results.push_back(run_experiment(*e, o, csv));

	print_table(results);
	write_convergence_svg(svg_path, convergence_plot(results, o));
	if (!csv.good()) std::printf("ERROR: could not write %s\n", csv_path.c_str());
	std::printf("\nwrote %s\nwrote %s\ntotal time %.0f s\n", csv_path.c_str(), svg_path.c_str(), seconds_since(start));
	return check_slopes(results) && csv.good() ? 0 : 1;
}

} // namespace

int main(int argc, char** argv) {
	try {
		return run(parse(argc, argv));
	} catch (const std::exception& e) { // a scene or an image that cannot be read or written
		std::fprintf(stderr, "error: %s\n", e.what());
		return 2;
	}
}

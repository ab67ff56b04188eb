#include "cli.h"
#include "cli_options.h"
#include "error.h"
#include "film_file.h"
#include "film_stream.h"
#include "follow_pixel.h"
#include "image_io.h"
#include "output_file.h"
#include "progressive_render.h"
#include "render.h"
#include "sample_rate_map.h"
#include "scene_loader.h"
#include "terminal.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ostream>

namespace {

// 1234567 -> "1.2 M"
std::string with_unit(double value) {
	const char* units[] = {"", " k", " M", " G"};
	int i = 0;
	for (; value >= 1000.0 && i < 3; i++) value /= 1000.0;
	char text[32];
	std::snprintf(text, sizeof text, "%.1f%s", value, units[i]);
	return text;
}

// Every output is checked before rendering, so that a path that cannot be written fails at once
// and no file is written.
void check_outputs(const Cli_Options& options) {
	for (const std::string& path : {options.png, options.exr, options.variance, options.nan_map, options.film}) {
		if (!path.empty()) check_writable(path);
	}
}

// Writes every requested image and returns their paths.
std::vector<std::string> write_outputs(const Film& film, const Render_Settings& settings, const Cli_Options& options) {
	std::vector<std::string> written;
	auto write = [&](const std::string& path, auto&& writer) {
		if (path.empty()) return;
		writer(path);
		written.push_back(path);
	};
	HDR_Image shown = options.samples_view ? sample_rate_map(film, settings.samples) : film.mean();
	write(options.png, [&](const std::string& path) { write_png(path, shown, options.exposure); });
	write(options.exr, [&](const std::string& path) { write_exr(path, shown); });
	write(options.variance, [&](const std::string& path) { write_exr(path, film.variance()); });
	write(options.nan_map, [&](const std::string& path) { write_png(path, film.non_finite_map()); });
	write(options.film, [&](const std::string& path) {
		write_film(path, film, Film_Origin{options.scene, settings.seed, settings.samples, options.pass, options.passes});
	});
	return written;
}

void warn_non_finite(const Film& film, const Cli_Options& options, std::ostream& err) {
	size_t pixels = size_t(std::count_if(film.pixels.begin(), film.pixels.end(),
	                                     [](const Pixel_Stats& p) { return p.non_finite > 0; }));
	err << "warning: " << film.non_finite() << " samples in " << pixels
	    << " pixels were NaN or infinite; they are left out of the image. ";
	if (options.nan_map.empty()) {
		err << "See where they are with --nan-map FILE.png.\n";
	} else {
		err << "They are marked white in " << options.nan_map << ".\n";
	}
}

std::string seconds_text(double seconds) {
	char text[32];
	std::snprintf(text, sizeof text, "%.3f s", seconds);
	return text;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
	return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The time a run took: loading the scene (a large mesh and its BVH take seconds) and rendering.
struct Run_Times {
	double loading = 0.0, rendering = 0.0;
};

void report(const Film& film, const Pathtracer& pathtracer, const Cli_Options& options, const Run_Times& times,
            const std::vector<std::string>& written, std::ostream& out) {
	const Render_Settings& settings = pathtracer.settings;
	const Estimator_Choice& estimator = pathtracer.estimator().choice;
	double seconds = times.rendering;
	for (const std::string& path : written) out << "wrote " << path << "\n";
	View view = options.view;
	// This pass's share: the sample indices options.pass - 1, + passes, ... below settings.samples.
	uint32_t share = (settings.samples + options.passes - options.pass) / options.passes;
	double samples = double(settings.width) * settings.height * share;
	char time[32];
	std::snprintf(time, sizeof time, "%.3f s", seconds);
	out << "rendered " << settings.width << " x " << settings.height << " pixels, "
	    << (options.adaptive > 0.0f ? "up to " : "") << share << (share == 1 ? " sample" : " samples") << " each";
	if (options.passes > 1)
		out << " (pass " << options.pass << " of " << options.passes << " of " << settings.samples << " samples)";
	out << ", view " << (options.samples_view ? "samples" : view_name(view));
	if (view == View::path)
		out << ", integrator " << estimator.integrator << ", sampler " << sampler_name(estimator.sampler);
	out << ", in " << time << "\n";
	if (options.adaptive > 0.0f) {
		uint64_t taken = 0;
		for (const Pixel_Stats& pixel : film.pixels) taken += pixel.count + pixel.non_finite;
		char mean[32];
		std::snprintf(mean, sizeof mean, "%.1f", double(taken) / double(film.pixels.size()));
		out << "adaptive sampling (threshold " << options.adaptive << "): " << mean
		    << " samples per pixel on average (see them with --view samples)\n";
		samples = double(taken);
	}
	out << "total: " << seconds_text(times.loading + times.rendering) << " (loading " << seconds_text(times.loading)
	    << ", rendering " << seconds_text(times.rendering) << ")\n";
	out << "speed: " << with_unit(samples / std::max(seconds, 1e-9)) << " samples/s (rendering)\n";
	out << "non-finite samples: " << film.non_finite() << "\n";
}

void render_and_write(const Scene& scene, const Cli_Options& options, Run_Times times, std::ostream& out,
                      std::ostream& err, bool err_is_terminal) {
	check_outputs(options);
	if (!options.quiet) out << "loaded " << options.scene << " in " << seconds_text(times.loading) << "\n" << std::flush;
	Pathtracer pathtracer(scene, scene.settings, options.view, estimator_choice(options));
	Progress_Bar progress_bar(err, err_is_terminal && !options.quiet);
	Render_Options render_options;
	render_options.threads = options.threads;
	render_options.pass = options.pass;
	render_options.passes = options.passes;
	render_options.adaptive.threshold = options.adaptive;
	render_options.progress = [&](size_t done, size_t total) { progress_bar.update(done, total); };

	auto start = std::chrono::steady_clock::now();
	Film film = render(pathtracer, render_options);
	times.rendering = seconds_since(start);
	progress_bar.finish();

	std::vector<std::string> written = write_outputs(film, pathtracer.settings, options);
	if (!options.quiet) report(film, pathtracer, options, times, written, out);
	if (film.non_finite() > 0) warn_non_finite(film, options, err);
}

// --stream (./lab view): the render in batches of samples, the film written after each batch
// (film_stream.h) by render_progressively, which keeps every thread rendering in between; batches
// of about STREAM_BATCH_SECONDS, so that the page updates several times a second. The film after N
// samples is render()'s with N, bit for bit; with --adaptive, each pixel stops as render()'s does.
void stream(const Scene& scene, const Cli_Options& options, std::ostream& out) {
	constexpr double STREAM_BATCH_SECONDS = 0.25;
	Pathtracer pathtracer(scene, scene.settings, options.view, estimator_choice(options));
	Progressive_Options progressive;
	progressive.render.threads = options.threads;
	progressive.render.adaptive.threshold = options.adaptive;
	progressive.samples = pathtracer.settings.samples;
	progressive.batch_seconds = STREAM_BATCH_SECONDS;
	progressive.frame = [&](const Film_Frame& frame) {
		write_frame(out, frame);
		return bool(out); // false: the viewer went away
	};
	render_progressively(pathtracer, progressive);
}

// --follow-pixel: the same paths the renderer takes for that pixel, printed ray by ray.
void follow(const Scene& scene, const Cli_Options& options, std::ostream& out) {
	Pathtracer pathtracer(scene, scene.settings, options.view, estimator_choice(options));
	auto [x, y] = *options.follow_pixel;
	if (x >= pathtracer.settings.width || y >= pathtracer.settings.height) {
		throw Input_Error("--follow-pixel: pixel (" + std::to_string(x) + ", " + std::to_string(y) +
		                  ") is outside the " + std::to_string(pathtracer.settings.width) + " x " +
		                  std::to_string(pathtracer.settings.height) + " image");
	}
	uint32_t samples = std::min(options.follow_samples, pathtracer.settings.samples);
	if (options.follow_json) {
		follow_pixel_json(pathtracer, x, y, samples, out, options.follow_brightest);
	} else {
		follow_pixel(pathtracer, x, y, samples, out);
	}
}

} // namespace

int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err, bool err_is_terminal,
            const std::string& integrator) {
	bool loading_line = false; // "loading SCENE ..." is on the terminal, to be erased
	try {
		if (wants_help(args)) {
			out << cli_usage(args);
			return 0;
		}
		if (wants_version(args)) {
			out << cli_version(args);
			return 0;
		}
		Cli_Options options;
		try {
			options = parse_cli_options(args);
		} catch (const Input_Error& e) {
			err << "error: " << e.what() << "\n";
			return CLI_USAGE_ERROR;
		}
		if (!options.integrator) options.integrator = integrator;
		// Loading is shown as it happens (a large mesh and its BVH take seconds) and then reported.
		bool show_loading = !options.quiet && !options.follow_pixel && !options.stream;
		std::string loading = "loading " + options.scene + " ...";
		if (show_loading && err_is_terminal) {
			err << loading << std::flush;
			loading_line = true;
		}
		auto start = std::chrono::steady_clock::now();
		Scene scene = load_scene(options.scene);
		override_scene(scene, options);
		Run_Times times;
		times.loading = seconds_since(start);
		if (loading_line) err << '\r' << std::string(loading.size(), ' ') << '\r' << std::flush;
		loading_line = false;
		if (options.follow_pixel) {
			follow(scene, options, out);
		} else if (options.stream) {
			stream(scene, options, out);
		} else {
			render_and_write(scene, options, times, out, err, err_is_terminal);
		}
		return 0;
	} catch (const std::exception& e) {
		// Input_Error from the options, the scene or an image file; std::bad_alloc for a film too large.
		if (loading_line) err << "\n";
		err << "error: " << e.what() << "\n";
		return 1;
	}
}

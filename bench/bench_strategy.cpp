#include "bench_strategy.h"
#include "bench_timing.h"
#include "cli_options.h"
#include "scene_loader.h"

#include <chrono>

Strategy_Setup set_up(const std::string& scene_path, const Strategy& strategy, uint32_t width, uint32_t height) {
	std::vector<std::string> args{"bench", scene_path, "--width", std::to_string(width), "--height",
	                              std::to_string(height)};
	args.insert(args.end(), strategy.flags.begin(), strategy.flags.end());
	Cli_Options cli = parse_cli_options(args);
	if (!cli.integrator) cli.integrator = "nee"; // pathtracer_reference's default (cli/main.cpp)
	Strategy_Setup setup{std::make_unique<Scene>(load_scene(scene_path)), {}, estimator_choice(cli)};
	override_environment(*setup.scene, cli);
	setup.scene->camera.aspect_ratio = float(width) / float(height);
	setup.settings = override_settings(setup.scene->settings, cli);
	return setup;
}

Timed_Render timed_render(const Strategy_Setup& setup, uint32_t spp, uint64_t seed, uint32_t threads,
                          float adaptive_threshold) {
	Render_Settings settings = setup.settings;
	settings.samples = spp;
	settings.seed = seed;
	Pathtracer pathtracer(*setup.scene, settings, View::path, setup.estimator);
	Render_Options options;
	options.threads = threads;
	options.adaptive.threshold = adaptive_threshold;
	Timed_Render result;
	double cpu_start = process_cpu_seconds();
	auto start = std::chrono::steady_clock::now();
	result.film = render(pathtracer, options);
	result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	result.cpu_seconds = process_cpu_seconds() - cpu_start;
	return result;
}

std::string joined(const std::vector<std::string>& words) {
	std::string text;
	for (const std::string& w : words) text += (text.empty() ? "" : " ") + w;
	return text;
}

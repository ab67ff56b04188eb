#pragma once
// A strategy of the run-time-against-error benchmarks (convergence, time-to-error): a name and a
// list of the renderer's own flags (framework/cli/cli_options.cpp), so that
// `pathtracer_reference SCENE FLAGS` renders exactly what the benchmark measures.
#include "estimator.h"
#include "render.h"

#include <memory>
#include <string>
#include <vector>

struct Strategy {
	std::string name;
	std::vector<std::string> flags;
};

// A strategy ready to render: its own scene (--env-sampling changes the scene)
// and settings, on a film of width x height (the camera takes the film's aspect ratio).
struct Strategy_Setup {
	std::unique_ptr<Scene> scene;
	Render_Settings settings;
	Estimator_Choice estimator;
};
Strategy_Setup set_up(const std::string& scene_path, const Strategy& strategy, uint32_t width, uint32_t height);

// One render of `spp` samples with `seed` on `threads` threads (0: all cores): the film, the wall
// time of render() and the CPU time the process used meanwhile (threads x wall time on an idle
// machine; less when other processes take the cores). With an adaptive threshold (render.h), spp
// is the most a pixel takes.
struct Timed_Render {
	Film film{0, 0};
	double seconds = 0.0, cpu_seconds = 0.0;
};
Timed_Render timed_render(const Strategy_Setup& setup, uint32_t spp, uint64_t seed, uint32_t threads,
                          float adaptive_threshold = 0.0f);

// The flags as one line of text.
std::string joined(const std::vector<std::string>& words);

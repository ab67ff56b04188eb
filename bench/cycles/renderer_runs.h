#pragma once
// The lab's reference renderer and Blender Cycles, each run as the command a user runs, on the same
// scene file at the same settings (bench/cycles/render_in_cycles.py matches Cycles' to ours), and
// what one run gives: its image, the time from the command's start to its exit, and the render time
// the renderer itself reports.
#include "hdr_image.h"

#include <cstdint>
#include <string>
#include <vector>

enum class Renderer { lab, cycles };
const char* renderer_name(Renderer renderer); // "ours", "Cycles 3.4"

struct Render_Request {
	std::string scene;
	uint32_t spp = 16;
	uint64_t seed = 0;
	uint32_t threads = 2;
	uint32_t max_depth = 0; // 0: the scene's
	std::vector<std::string> cycles_defaults; // render_in_cycles.py --cycles-default NAME: Cycles' own setting kept
	std::vector<std::string> cycles_options;  // more render_in_cycles.py options, e.g. --light-as-mesh
	std::vector<std::string> lab_options;     // more options of our renderer, e.g. --light-choice power
};

struct Renderer_Run {
	HDR_Image image;
	double command_seconds = 0.0; // from starting the command to its exit (startup, loading, render, writing)
	double render_seconds = 0.0;  // what the renderer reports: ours "rendering", Cycles' the render call
	double mean_spp = 0.0;        // ours with --adaptive: the samples a pixel took on average (0: not reported)
};

// Runs the renderer; `work_dir` holds its image and log. Throws std::runtime_error with the end of
// the log when the command fails.
Renderer_Run run_renderer(Renderer renderer, const Render_Request& request, const std::string& work_dir);

// "0.22 0.28 0.29": the 1, 5 and 15 minute load averages.
std::string load_average();

// One or two numbers as text by a printf format, e.g. fmt("%+.2f ± %.2f", difference, error).
std::string fmt(const char* format, double a, double b = 0.0);

// ---- Images and their noise -----------------------------------------------------------------------

// The mean of two independent renders A and B and the variance of that mean per pixel channel,
// estimated as (A - B)^2 / 4 (unbiased, one degree of freedom per pixel channel).
struct Noisy_Image {
	HDR_Image mean, variance;
};
Noisy_Image from_two_halves(const HDR_Image& a, const HDR_Image& b);

// relMSE = mean over pixel channels of (x - r)^2 / (r^2 + 0.01): the graders' definition
// (convergence_metrics.h).
double rel_mse(const HDR_Image& x, const HDR_Image& r);
// What the noise of `noisy` adds to the expected relMSE against r: mean of variance / (r^2 + 0.01).
double noise_rel_mse(const Noisy_Image& noisy, const HDR_Image& r);

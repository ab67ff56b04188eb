#pragma once
// The renderer's command-line options (see cli.h): parsing with one clear error per mistake, and
// the --help text, both from one table so they cannot disagree.
#include "estimator.h"
#include "pathtracer.h"

#include <optional>
#include <string>
#include <vector>

// What the command line asks for. Unset optionals keep the scene's own settings.
struct Cli_Options {
	std::string scene;
	// Output files; png defaults to out/<scene stem>.png, from pathtracer_student to
	// out/<scene stem>_student.png.
	std::string png, exr, variance, nan_map;
	std::string film; // --film: the film's statistics, for merging passes (film_file.h)
	uint32_t pass = 1, passes = 1; // --pass P/N: this render's share of the samples (render.h)
	std::optional<uint32_t> samples, width, height, max_depth;
	std::optional<uint64_t> seed;
	uint32_t threads = 0; // 0 = all hardware threads
	View view = View::path;
	bool samples_view = false; // --view samples: the path tracer's render, shown as its sample counts
	float adaptive = 0.0f;     // --adaptive: the threshold of adaptive sampling (adaptive_sampling.h); 0: off
	float exposure = 0.0f; // stops, for the PNG
	bool quiet = false;
	// Strategy switches, each the same image with other noise: --no-light-sampling, --no-roulette,
	// --env-sampling, --sampler, --integrator, --light-choice.
	bool light_sampling = true, russian_roulette = true;
	std::optional<bool> env_importance_sampling; // unset: as the scene says
	Sampler sampler = Sampler::sobol;          // renders default to low-discrepancy samples
	std::optional<std::string> integrator;    // unset: the program's default (run_cli)
	std::optional<Light_Choice> light_choice; // unset: the integrator's (integrators.h)
	// --follow-pixel X,Y: print the life of that pixel's rays instead of rendering an image.
	std::optional<std::pair<uint32_t, uint32_t>> follow_pixel;
	uint32_t follow_samples = 1;
	bool follow_json = false;     // --follow-format json
	uint32_t follow_brightest = 0; // --follow-brightest K (json only): the K brightest samples
	// --stream (./lab view): render progressively, writing the film to standard output after each
	// batch of samples (film_stream.h), instead of writing images.
	bool stream = false;
};

// args as in argv (args[0] is the program name). Throws Input_Error naming the bad option/value.
Cli_Options parse_cli_options(const std::vector<std::string>& args);

// The scene's settings with the command line's overrides. Throws Input_Error for a film larger than
// Render_Settings::MAX_PIXELS.
Render_Settings override_settings(Render_Settings settings, const Cli_Options& options);

// The estimator the command line asks for: its integrator (mixture where it names none), sampler
// and light choice (where it names none, the integrator's).
Estimator_Choice estimator_choice(const Cli_Options& options);

// --env-sampling: rebuilds the scene's image environment as uniformly or importance-sampled. Throws
// Input_Error if the scene has no image environment, or importance sampling is asked of a black one.
void override_environment(Scene& scene, const Cli_Options& options);

// All of the command line's overrides of a loaded scene: override_settings into scene.settings,
// override_environment, and, when --width or --height give the film another shape, the camera's
// aspect ratio = width / height with the same vertical field of view (the view widens or narrows;
// the picture is never stretched).
void override_scene(Scene& scene, const Cli_Options& options);

// --help (or -h): whether it was asked for, and the text, within 80 columns.
bool wants_help(const std::vector<std::string>& args);
std::string cli_usage(const std::vector<std::string>& args);

// --version: whether it was asked for, and the line "<program> (PathTracer Lab) <version>".
bool wants_version(const std::vector<std::string>& args);
std::string cli_version(const std::vector<std::string>& args);

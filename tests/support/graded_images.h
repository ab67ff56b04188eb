#pragma once
// The graded image scenes (scenes/graded/) and their stored references (scenes/graded/references/):
// <scene>_mean.exr, <scene>_var.exr (per-sample variance), <scene>_m4.exr (per-sample fourth central
// moment, for the bound on a render's noise) and <scene>.json, the settings that made them and the
// outliers of correct renders (image_compare.h). A scene's own "film" block holds the graders'
// settings (size, samples, max_depth, seed); the references use the same size and depth,
// REFERENCE_SPP_FACTOR times the samples and their own seed. The instructors regenerate them (make_references, in their repository).
#include "film.h"
#include "image_compare.h"
#include "pathtracer.h"
#include "render.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

struct Graded_Scene {
	std::string name; // scenes/graded/<name>.json
	View view;        // the eye view for tasks 1-3, which do not shade
	// The integrators the graders render it with (image_compare.h: their outliers are counted for each).
	std::vector<std::string> integrators{"mixture"};
};

const std::vector<Graded_Scene>& graded_scenes();
const Graded_Scene& graded_scene(const std::string& name);

constexpr uint32_t REFERENCE_SPP_FACTOR = 64;
constexpr uint64_t REFERENCE_SEED = 1000003; // different from every grader and calibration seed
// The outlier counts (image_compare.h): renders with the graders' settings and seeds
// OUTLIER_SEED, OUTLIER_SEED + 1, ... (different from the graders' public seeds and those of the
// instructors' calibration test).
constexpr uint32_t OUTLIER_RENDERS = 100;
constexpr uint64_t OUTLIER_SEED = 2000003;

std::string graded_scene_file(const std::string& name);
std::string reference_file(const std::string& name, const std::string& suffix); // "_mean.exr", ".json"

// Checksums: make_references records the SHA-256 of every graded scene and reference file in
// scenes/graded/references/SHA256SUMS; reading one that differs (or has none) is an Input_Error,
// never a pass.
inline const std::string GRADED_CHECKSUMS = "scenes/graded/references/SHA256SUMS";
void record_checksums();
void verify_checksum(const std::string& file, const std::string& checksums = GRADED_CHECKSUMS);

// The scene (its checksum verified); its settings are the graders' (the file's "film").
Scene load_graded(const Graded_Scene& graded);

// Renders a graded scene with its own size and depth, and the given samples and seed.
Film render_graded(const Graded_Scene& graded, const Scene& scene, uint32_t samples, uint64_t seed,
                   const Render_Options& options = Render_Options{});

// The stored reference; throws with the file name if it is missing, differs from its checksum, or
// was made with another size, depth or view than `grader` (the scene's settings) has.
Image_Estimate read_reference(const Graded_Scene& graded, const Render_Settings& grader);
// The outliers of correct renders with grader's settings and integrator (image_compare.h), from the
// reference's record; throws with the file name if it has none for them.
Image_Calibration read_calibration(const Graded_Scene& graded, const Render_Settings& grader,
                                   const std::string& integrator);
// The reference image and its record without outlier counts (make_references adds them after).
void write_reference(const Graded_Scene& graded, const Film& film, const Render_Settings& settings);
// Counts the outliers of OUTLIER_RENDERS renders with the graders' settings for each of the scene's
// integrators against the stored reference, and adds them to its record (`progress` is told each
// render).
void count_reference_outliers(const Graded_Scene& graded, const std::function<void(size_t, size_t)>& progress = {});

// A render compared with the stored reference.
struct Reference_Check {
	Image_Comparison comparison;
	uint64_t non_finite = 0;
	Image_Estimate render, reference; // the images compared
};
// `film`, rendered with the scene's `settings` (size, depth, samples) and `integrator`, compared
// with the stored reference at significance alpha (image_compare.h).
Reference_Check compare_with_reference(const Graded_Scene& graded, const Film& film, const Render_Settings& settings,
                                       const std::string& integrator, double alpha = IMAGE_ALPHA);
// The same against a given reference and its outlier counts (a varied scene's, graded_variation.h).
Reference_Check compare_with(const Film& film, const Render_Settings& settings, Image_Estimate reference,
                             const Image_Calibration& calibration, double alpha = IMAGE_ALPHA);

// Renders the scene with the reference implementation and the graders' settings (and `seed` if
// given) and compares the render with the stored reference.
Reference_Check check_against_reference(const Graded_Scene& graded,
                                        std::optional<uint64_t> seed = std::nullopt);

#pragma once
// The graded image scenes (scenes/graded/) and their stored references (scenes/graded/references/):
// <scene>_mean.exr, <scene>_var.exr (per-sample variance) and <scene>.json, the settings that made
// them. A scene's own "film" block holds the graders' settings (size, samples, max_depth, seed);
// the references use the same size and depth, REFERENCE_SPP_FACTOR times the samples and their
// own seed. The instructors regenerate them (make_references, in their repository).
#include "film.h"
#include "image_compare.h"
#include "pathtracer.h"
#include "render.h"

#include <optional>
#include <string>
#include <vector>

struct Graded_Scene {
	std::string name; // scenes/graded/<name>.json
	View view;        // the eye view for tasks 1-3, which do not shade
};

const std::vector<Graded_Scene>& graded_scenes();
const Graded_Scene& graded_scene(const std::string& name);

constexpr uint32_t REFERENCE_SPP_FACTOR = 64;
constexpr uint64_t REFERENCE_SEED = 1000003; // different from every grader and calibration seed

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
void write_reference(const Graded_Scene& graded, const Film& film, const Render_Settings& settings);

// A render compared with the stored reference.
struct Reference_Check {
	Image_Comparison comparison;
	uint64_t non_finite = 0;
	Image_Estimate render, reference; // the images compared
};
// `film`, rendered with the scene's `settings` (size, depth), compared with the stored reference.
Reference_Check compare_with_reference(const Graded_Scene& graded, const Film& film, const Render_Settings& settings);

// Renders the scene with the reference implementation and the graders' settings (and `seed` if
// given) and compares the render with the stored reference.
Reference_Check check_against_reference(const Graded_Scene& graded,
                                        std::optional<uint64_t> seed = std::nullopt);

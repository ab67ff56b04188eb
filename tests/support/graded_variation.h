#pragma once
// The graded scenes under an instructor's grading seed (DESIGN.md, decided point 7): students hold
// every graded scene and its reference image, so an official grade never compares with those. The
// seed varies each graded scene where an answer copied from the public one would show, and the
// judge renders the varied scene's reference itself:
//   - the camera orbits its target by up to 10 degrees, tilts by up to 4, and its field of view
//     changes by up to 7 %;
//   - every diffuse albedo, mirror reflectance and glass transmittance keeps 70 % to 100 % of each
//     channel, emission and environment light 75 % to 125 %, and glass takes an index of
//     refraction from 1.35 to 1.7;
//   - every sphere, and every mesh smaller than half the scene (the blocks and the light of a
//     Cornell box, a bunny; not its walls or a floor), turns about the vertical through its centre
//     by up to 20 degrees and moves sideways by up to 15 % of its size.
// The varied scene is the scene file's description with these changes (transform steps appended to
// each object's), read by the framework's loader.
#include "graded_images.h"
#include "rng.h"

#include <nlohmann/json.hpp>

#include <string>

// The graded scene's description as `rng` varies it (see above).
nlohmann::ordered_json vary_graded_scene(const Graded_Scene& graded, RNG& rng);

// A varied scene's reference (image_compare.h), rendered by the judge with the reference
// implementation, the grader's settings (size, depth, view, estimator) and REFERENCE_SPP_FACTOR
// times its samples, as REFERENCE_SPP_FACTOR passes of the grader's samples each (render.h). Each
// pass is also a correct render of the grader's samples: its outliers against the other passes
// together are what the outlier test allows (Image_Calibration), so no further renders are needed.
// Kept in the folder LAB_REFERENCE_CACHE names (if set and writable), keyed by the SHA-256 of the
// description and settings: a class graded with one seed renders each once. Instructors keep
// that folder secret, as the seed.
struct Judge_Reference {
	Image_Estimate reference;
	Image_Calibration calibration;
};
Judge_Reference judge_reference(const Graded_Scene& graded, const nlohmann::ordered_json& description,
                                const Render_Settings& grader, const std::string& integrator);

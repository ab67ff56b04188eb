#pragma once
// Every call of the student's code in the grader of task 6's optional extension (next-event
// estimation, handout §6.5), in one place: each is one request to the subject (grading/judge/), and
// the tests only ever see the numbers these return.
#include "film.h"
#include "material.h"
#include "scene.h"

#include <vector>

// power_heuristic(pdf_f, pdf_g) for each pair (x: pdf_f, y: pdf_g).
std::vector<float> student_power_heuristic(const std::vector<Vec2>& pairs);

// n values of Pathtracer(scene, settings).estimate_direct at `point` (a lifted hit record),
// averaged over the RGB channels, from one generator seeded with `seed`.
std::vector<double> student_direct_light(const Scene& scene, const Render_Settings& settings, const Trace& point,
                                         const BSDF& bsdf, Vec3 out_dir, size_t n, uint64_t seed);

// n samples of pixel (0, 0) rendered by the NEE integrator (which calls estimate_direct and
// power_heuristic), averaged over the RGB channels, with the film's per-sample generators.
std::vector<double> student_pixel_samples(const Scene& scene, const Render_Settings& settings, size_t n);

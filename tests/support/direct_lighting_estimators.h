#pragma once
// One-sample estimates of the light a surface point reflects, for the task 6 grader. The point is a
// hit record made by hand (no receiver geometry needed); the radiance arriving along a direction is
// the emission of the first surface hit (or the environment), as the path tracer sees it with
// max_depth = 1.
#include "pathtracer.h"
#include "sample_moments.h"

#include <vector>

// A hit record at `position` on a surface with unit normal `normal`.
Trace surface_point(Vec3 position, Vec3 normal);

// Radiance arriving at `from` from direction `dir` (unit, world space, pointing away from `from`):
// the emission of the closest surface along the ray towards its origin, else the environment.
Spectrum arriving_radiance(const Scene& scene, Vec3 from, Vec3 dir);

// The grader's own strategies, for comparison with the student's mixture (sample_incoming).
enum class Strategy {
	bsdf,    // BSDF::scatter in the local frame, with density BSDF::pdf
	lights,  // Pathtracer::sample_area_lights, with density area_lights_pdf
	mixture, // the reference's Pathtracer::sample_incoming (the judge links the reference of every task)
};

// One direction drawn with `strategy`, as sample_incoming would return it.
Incoming_Sample draw(const Pathtracer& pt, Strategy strategy, RNG& rng, const Trace& point, const BSDF& bsdf,
                     Vec3 out_dir);

// The sample of L_o = f * L_in * |cos theta| / pdf that a direction gives (the attenuation alone
// for a discrete sample; 0 when pdf = 0), averaged over the RGB channels.
double reflected_radiance_sample(const Scene& scene, const Trace& point, const Incoming_Sample& s);

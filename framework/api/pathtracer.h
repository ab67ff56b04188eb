#pragma once
// The path tracer: per-pixel sampling (task 1), the estimator (task 4), the choice of the next
// direction (task 6), and the framework's light sampling and debug views.
//
// Depth: a camera ray has depth 0 and each bounce adds 1. A surface hit by a ray of depth d may
// scatter only while d < max_depth, so max_depth = 0 shows emitters only, max_depth = 1 adds
// direct lighting (one bounce), and so on.
#include "scene.h"
#include "spawn_ray.h"

#include <cstdint>
#include <memory>
#include <string>

// What a render shows. `path` is the path tracer; the others are debug views (framework code
// that needs only tasks 1-3).
enum class View {
	path,      // Monte Carlo path tracing (task 4 onwards)
	eye_light, // albedo * |cos| of the first hit, lit from the eye, plus emission: Part I pictures
	normals,   // first-hit normal mapped to colour (n + 1) / 2
	albedo,    // first-hit albedo (BSDF::albedo)
	bvh,       // BVH node visits per ray, as a heat map
	direction, // camera-ray direction mapped to colour (d + 1) / 2
};
bool parse_view(const std::string& name, View& view);
const char* view_name(View view);

// The next direction of a path, in world space (task 6).
struct Incoming_Sample {
	Vec3 direction;       // unit, world space, pointing away from the surface
	Spectrum attenuation; // as in Scatter (material.h)
	float pdf = 0.0f;     // solid-angle density the direction was drawn with; unused if discrete
	bool discrete = false;
};

// A point on a light and what it sends towards a surface point (Pathtracer::sample_light).
struct Light_Sample {
	Vec3 direction{0.0f};     // unit, world space, from the surface point towards the light
	float distance = INF_F;   // to the point on the light (INF_F: the environment)
	Spectrum radiance{0.0f};  // what the light emits towards the surface point (0 from a light's back)
	float pdf = 0.0f;         // the density of this sample, per solid angle
	// A shadow ray must end short of the light, or it hits the light itself: at
	// SHADOW_RAY_END * distance.
	static constexpr float SHADOW_RAY_END = 1.0f - 1e-4f;
};

// Optional extension of task 6 (student/task6_direct_lighting.cpp, handout §6.5): Veach's power
// heuristic, the weight of a sample drawn by strategy f that strategy g could also have drawn:
// pdf_f^2 / (pdf_f^2 + pdf_g^2), each pdf the density of the same direction.
float power_heuristic(float pdf_f, float pdf_g);

// The framework's estimator of a render (framework/render/estimator.h): its integrator, random
// numbers and choice of lights.
struct Estimator;
struct Estimator_Choice;

class Pathtracer {
public:
	// With the lab's estimator, the graders': task 4's shade() continuing paths in the directions
	// task 6's sample_incoming() chooses, independent random numbers, lights chosen by power.
	Pathtracer(const Scene& scene, Render_Settings settings, View view = View::path);
	// Framework: with another estimator of the same image (--integrator, --sampler, --light-choice).
	Pathtracer(const Scene& scene, Render_Settings settings, View view, const Estimator_Choice& estimator);

	// Task 1 (student/task1_camera.cpp): one supersampling sample of pixel (x, y): a point chosen
	// uniformly at random in the pixel, the camera ray through it, and trace() of that ray.
	Spectrum trace_pixel(uint32_t x, uint32_t y, RNG& rng) const;

	// Framework: radiance arriving along `ray` in the selected view. For View::path, the estimate
	// of the estimator's integrator: by default task 4's, which intersects the scene and returns
	// the environment on a miss and shade() on a hit.
	Spectrum trace(RNG& rng, const Ray& ray) const;

	// Task 4 (student/task4_path.cpp): the radiance leaving hit.position towards ray.point:
	// emission plus a one-sample estimate of reflected light, continuing the path with trace().
	Spectrum shade(RNG& rng, const Ray& ray, const Trace& hit) const;
	// Russian roulette (handout §4.3) may end a path from this depth on: the first bounces carry
	// most of the image and are never cut. Task 4's reference and the framework's integrators
	// start there.
	static constexpr uint32_t ROULETTE_DEPTH = 3;

	// Task 6 (student/task6_direct_lighting.cpp): the direction to continue a path from `hit`
	// (out_dir: unit, world space, towards the previous vertex), by BSDF sampling or, for
	// continuous BSDFs in scenes with lights, the one-sample mixture of BSDF and light sampling.
	Incoming_Sample sample_incoming(RNG& rng, const Trace& hit, const BSDF& bsdf, Vec3 out_dir) const;

	// Framework, for task 6: a unit direction from `from` towards a random point on the lights
	// (emissive shapes and the environment), and the solid-angle density of choosing `dir` that
	// way. Only meaningful when has_lights().
	Vec3 sample_area_lights(RNG& rng, Vec3 from) const;
	float area_lights_pdf(Vec3 from, Vec3 dir) const;
	bool has_lights() const; // false without lights, or when settings.light_sampling is off

	// Framework, for task 6's extension: a light chosen as sample_area_lights chooses it, and on it a
	// point (or a direction of the environment), with its distance, what it emits towards `from`,
	// and the density of choosing it: (probability of the light) * dist^2 / (|cos theta_light| area).
	// Only meaningful when has_lights().
	Light_Sample sample_light(RNG& rng, Vec3 from) const;

	// Optional extension of task 6 (handout §6.5): next-event estimation at `hit` (out_dir: unit,
	// world space, towards the previous vertex; hit.position already lifted off the surface): the
	// light reflected towards out_dir from one light sample, f * L * |cos theta| / pdf, weighted by
	// the power heuristic against BSDF sampling, and 0 if the shadow ray is blocked. The NEE
	// integrator (--integrator nee, framework/render/integrators/nee_integrator.h) adds it at every
	// vertex of a continuous BSDF in a scene with lights, and weights the emission its BSDF samples
	// find by the heuristic.
	Spectrum estimate_direct(RNG& rng, const Trace& hit, const BSDF& bsdf, Vec3 out_dir) const;

	// Framework: the Part I shading (View::eye_light) of a hit.
	Spectrum eye_light(const Ray& ray, const Trace& hit) const;

	const Scene& scene;
	Render_Settings settings; // image size, samples, max_depth, seed
	View view = View::path;

	// Framework: the estimator, which also decides which light sample_area_lights and
	// sample_light aim at.
	const Estimator& estimator() const;

private:
	Spectrum debug_view(const Ray& ray) const;

	std::shared_ptr<const Estimator> chosen;
};

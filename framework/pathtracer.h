#pragma once
// The path tracer: per-pixel sampling (task 1), the estimator (task 4), the choice of the next
// direction (task 6), and the framework's light sampling and debug views.
//
// Depth: a camera ray has depth 0 and each bounce adds 1. A surface hit by a ray of depth d may
// scatter only while d < max_depth, so max_depth = 0 shows emitters only, max_depth = 1 adds
// direct lighting (one bounce), and so on.
#include "scene.h"

#include <string>

// What a render shows. `path` is the path tracer; the others are debug views (framework code
// that needs only tasks 1-3).
enum class View {
	path,      // Monte Carlo path tracing (task 4 onwards)
	eye_light, // albedo * |cos| of the first hit, lit from the eye, plus emission: Part I pictures
	normals,   // first-hit normal mapped to colour (n + 1) / 2
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

class Pathtracer {
public:
	Pathtracer(const Scene& scene, Render_Settings settings, View view = View::path);

	// Task 1 (student/task1_camera.cpp): one supersampling sample of pixel (x, y): a point chosen
	// uniformly at random in the pixel, the camera ray through it, and trace() of that ray.
	Spectrum trace_pixel(uint32_t x, uint32_t y, RNG& rng) const;

	// Framework: radiance arriving along `ray` in the selected view. For View::path it intersects
	// the scene, returns the environment on a miss and shade() on a hit.
	Spectrum trace(RNG& rng, const Ray& ray) const;

	// Task 4 (student/task4_path.cpp): the radiance leaving hit.position towards ray.point:
	// emission plus a one-sample estimate of reflected light, continuing the path with trace().
	Spectrum shade(RNG& rng, const Ray& ray, const Trace& hit) const;

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

	// Framework: the Part I shading (View::eye_light) of a hit.
	Spectrum eye_light(const Ray& ray, const Trace& hit) const;

	const Scene& scene;
	Render_Settings settings; // image size, samples, max_depth, seed
	View view = View::path;

private:
	Spectrum debug_view(const Ray& ray) const;
};

#pragma once
// How the radiance along the rays of a path is estimated (View::path). Pathtracer::trace hands each
// ray to its estimator's integrator (estimator.h), which works above the Pathtracer, through its
// public functions; the integrators are chosen by name (integrators.h). Each spawns every ray with
// spawn_ray (spawn_ray.h).
#include "render_observer.h"
#include "rng.h"
#include "scene.h"

class Pathtracer;

class Path_Integrator {
public:
	virtual ~Path_Integrator() = default;
	// The radiance arriving along `ray`.
	virtual Spectrum radiance(const Pathtracer& pathtracer, RNG& rng, const Ray& ray) const = 0;
};

// One ray of a path, as every integrator traces it: its closest hit in the scene, shaded by
// shade(hit), or missed() where it leaves the scene. The sampler is told the ray's vertex
// (RNG::begin_vertex), the render observer the ray, its hit and its radiance.
template <class Shade, class Missed>
Spectrum trace_path_ray(const Scene& scene, RNG& rng, const Ray& ray, Shade shade, Missed missed) {
	rng.begin_vertex(ray.depth);
	return observe<Ray_Traced>(
		[&] {
			Trace hit = observe<Closest_Hit>([&] { return scene.hit(ray); }, ray);
			return hit.hit ? shade(hit) : missed(hit);
		},
		ray);
}

#pragma once
// How the radiance along the rays of a path is estimated (View::path). Pathtracer::trace hands each
// ray to the integrator its settings name (Integrator, scene.h); an integrator works above the
// Pathtracer, through its public functions:
//   - Integrator::mixture: task 4's estimator, Pathtracer::shade, which continues paths in the
//     directions task 6's sample_incoming chooses (path_integrator.cpp);
//   - Integrator::nee: next-event estimation with multiple importance sampling (nee_integrator.h).
// Both spawn every ray with spawn_ray (spawn_ray.h).
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

// The integrator `which` names.
const Path_Integrator& path_integrator(Integrator which);

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

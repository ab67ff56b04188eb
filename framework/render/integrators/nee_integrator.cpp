#include "nee_integrator.h"
#include "estimator.h"
#include "frame.h"
#include "integrators.h"

#include <algorithm>

namespace {

// How a ray left its vertex: what the emission it finds is weighted by.
struct Arrival {
	bool light_sampled = false; // the vertex also took a light sample (else: full weight)
	float bsdf_pdf = 0.0f;      // the density of the BSDF sample that chose the ray's direction
};

// The weight of the emission that `ray` found at `hit`, by the power heuristic against light
// sampling (1 if its vertex took no light sample).
float emission_weight(const Pathtracer& pt, const Arrival& arrival, const Ray& ray, const Trace& hit) {
	if (!arrival.light_sampled) return 1.0f;
	return power_heuristic(arrival.bsdf_pdf, light_pdf(pt, ray, hit));
}

float max_component(Spectrum s) {
	return std::max({s.r, s.g, s.b});
}

Spectrum radiance_along(const Pathtracer& pt, RNG& rng, const Ray& ray, const Arrival& arrival);

// The radiance leaving `hit` towards the ray's origin: emission (weighted), the light sample, and
// the BSDF sample continuing the path. Flattened: everything it calls but the next ray's trace is
// compiled into it (the light sample, the shadow ray's setup, the BSDF, the random numbers), so that a
// vertex runs as one stretch of code, without calls that pass vectors through memory (7 % of a
// Cornell box render: bench/README.md, "Issue 37: the Cornell box").
[[gnu::flatten]] Spectrum shade_nee(const Pathtracer& pt, RNG& rng, const Ray& ray, const Trace& hit,
                                    const Arrival& arrival) {
	const Material& material = pt.scene.materials[hit.material];
	Frame frame = Frame::from_normal(hit.normal);
	Vec3 out_dir = -glm::normalize(ray.dir);
	Spectrum radiance = material.emitted(frame.to_local(out_dir));
	if (radiance != Spectrum{0.0f}) radiance *= emission_weight(pt, arrival, ray, hit);
	if (ray.depth >= pt.settings.max_depth || material.bsdf.is_black()) return radiance;

	// Light samples, and their densities, are taken from where the next ray starts (task 4).
	const BSDF& bsdf = material.bsdf;
	Trace from = hit;
	from.position = lifted(hit, out_dir);
	bool light_sampled = !bsdf.is_discrete() && pt.has_lights();
	if (light_sampled) radiance += pt.estimate_direct(rng, from, bsdf, out_dir);

	Vec3 out_local = frame.to_local(out_dir);
	Scatter s = bsdf.scatter(rng, out_local);
	float pdf = bsdf.is_discrete() ? 0.0f : bsdf.pdf(out_local, s.direction);
	Spectrum weight = bsdf.is_discrete() ? s.attenuation
	                  : pdf > 0.0f       ? s.attenuation * std::abs(s.direction.y) / pdf
	                                     : Spectrum{0.0f};
	if (weight == Spectrum{0.0f}) return radiance;
	// Russian roulette as task 4 plays it (reference/task4_path.cpp: q = min(1, max(largest albedo
	// component, largest weight component)), from its depth on.
	if (pt.settings.russian_roulette && ray.depth >= Pathtracer::ROULETTE_DEPTH) {
		float q = std::min(1.0f, std::max(max_component(bsdf.albedo()), max_component(weight)));
		if (q < 1.0f) {
			if (!rng.coin_flip(q)) return radiance;
			weight /= q;
		}
	}
	Ray next = spawn_ray(hit, frame.to_world(s.direction), ray.depth + 1);
	return radiance + weight * radiance_along(pt, rng, next, Arrival{light_sampled, pdf});
}

// The radiance arriving along `ray`.
Spectrum radiance_along(const Pathtracer& pt, RNG& rng, const Ray& ray, const Arrival& arrival) {
	return trace_path_ray(
		pt.scene, rng, ray, [&](const Trace& hit) { return shade_nee(pt, rng, ray, hit, arrival); },
		[&](const Trace& miss) {
			return pt.scene.environment_radiance(ray.dir) * emission_weight(pt, arrival, ray, miss);
		});
}

class Nee_Integrator : public Path_Integrator {
public:
	Spectrum radiance(const Pathtracer& pt, RNG& rng, const Ray& ray) const override {
		return radiance_along(pt, rng, ray, Arrival{});
	}
};

const Nee_Integrator nee;
const Integrator_Row row{"nee",
                         "next-event estimation with MIS: a shadow ray to a light at every bounce "
                         "(pathtracer_reference's default)",
                         nee, Light_Choice::tree};

} // namespace

float light_pdf(const Pathtracer& pt, const Ray& ray, const Trace& hit) {
	const Scene& scene = pt.scene;
	const Light_Distribution& lights = pt.estimator().lights;
	if (!hit.hit) {
		if (!scene.environment) return 0.0f;
		float chosen = lights.probability(scene.area_lights.count(), ray.point);
		return chosen * std::visit([&](const auto& env) { return env.pdf(ray.dir); }, *scene.environment);
	}
	int light = scene.area_lights.light_of(hit.object);
	if (light < 0) return 0.0f;
	return lights.probability(size_t(light), ray.point) *
	       scene.area_lights.point_pdf(size_t(light), ray.point, hit.position, hit.normal);
}

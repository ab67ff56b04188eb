#include "path_integrator.h"
#include "nee_integrator.h"
#include "pathtracer.h"

namespace {
// Task 4's estimator: the closest hit, shaded by Pathtracer::shade; the environment on a miss.
class Shading_Integrator : public Path_Integrator {
public:
	Spectrum radiance(const Pathtracer& pt, RNG& rng, const Ray& ray) const override {
		return trace_path_ray(
			pt.scene, rng, ray, [&](const Trace& hit) { return pt.shade(rng, ray, hit); },
			[&](const Trace&) { return pt.scene.environment_radiance(ray.dir); });
	}
};
} // namespace

const Path_Integrator& path_integrator(Integrator which) {
	static const Shading_Integrator shading;
	return which == Integrator::nee ? nee_integrator() : shading;
}

#include "direct_lighting_estimators.h"
#include "frame.h"

#include <cmath>

Trace surface_point(Vec3 position, Vec3 normal) {
	Trace t;
	t.hit = true;
	t.position = position;
	t.normal = glm::normalize(normal);
	t.origin = position + t.normal; // some point in front of the surface
	t.distance = 1.0f;
	return t;
}

Spectrum arriving_radiance(const Scene& scene, Vec3 from, Vec3 dir) {
	Trace hit = scene.hit(Ray(from, dir, Vec2{1e-4f, INF_F}));
	if (!hit.hit) return scene.environment_radiance(dir);
	// Emission is one-sided: out_dir in the light's local frame has y = cos towards `from`.
	return scene.materials[hit.material].emitted(Vec3{0.0f, glm::dot(-dir, hit.normal), 0.0f});
}

namespace {
double channel_average(Spectrum s) {
	return (double(s.r) + double(s.g) + double(s.b)) / 3.0;
}
} // namespace

Incoming_Sample draw(const Pathtracer& pt, Strategy strategy, RNG& rng, const Trace& point, const BSDF& bsdf,
                     Vec3 out_dir) {
	if (strategy == Strategy::mixture) return pt.sample_incoming(rng, point, bsdf, out_dir);
	Frame frame = Frame::from_normal(point.normal);
	Vec3 out_local = frame.to_local(out_dir);
	if (strategy == Strategy::bsdf) {
		Scatter s = bsdf.scatter(rng, out_local);
		return Incoming_Sample{frame.to_world(s.direction), s.attenuation, bsdf.pdf(out_local, s.direction),
		                       bsdf.is_discrete()};
	}
	Vec3 dir = pt.sample_area_lights(rng, point.position);
	return Incoming_Sample{dir, bsdf.evaluate(out_local, frame.to_local(dir)), pt.area_lights_pdf(point.position, dir),
	                       false};
}

double reflected_radiance_sample(const Scene& scene, const Trace& point, const Incoming_Sample& s) {
	Spectrum weight = s.discrete ? s.attenuation
	                  : s.pdf > 0.0f ? s.attenuation * std::abs(glm::dot(s.direction, point.normal)) / s.pdf
	                                 : Spectrum{0.0f};
	if (weight == Spectrum{0.0f}) return 0.0;
	return channel_average(weight * arriving_radiance(scene, point.position, s.direction));
}

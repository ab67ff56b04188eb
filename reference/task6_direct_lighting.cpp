// Task 6: direct lighting. Handout: handouts/task6_direct_lighting.md
#include "pathtracer.h"
#include "frame.h"

Incoming_Sample Pathtracer::sample_incoming(RNG& rng, const Trace& hit, const BSDF& bsdf, Vec3 out_dir) const {
	// BSDFs work in the local frame (normal +y), lights in world space (handout §6.3).
	Frame frame = Frame::from_normal(hit.normal);
	Vec3 out_local = frame.to_local(out_dir);

	// A discrete BSDF has no density to mix with, and without lights there is nothing to aim at:
	// plain BSDF sampling (handout §6.2).
	if (bsdf.is_discrete() || !has_lights()) {
		Scatter s = bsdf.scatter(rng, out_local);
		return Incoming_Sample{frame.to_world(s.direction), s.attenuation, bsdf.pdf(out_local, s.direction),
		                       bsdf.is_discrete()};
	}

	// One-sample mixture: a fair coin picks the strategy (handout §6.2).
	Vec3 in_local, in_world;
	if (rng.coin_flip(0.5f)) {
		in_local = bsdf.scatter(rng, out_local).direction;
		in_world = frame.to_world(in_local);
	} else {
		in_world = sample_area_lights(rng, hit.position);
		in_local = frame.to_local(in_world);
	}

	// Whichever strategy drew it, the direction could have come from either, so its density is the
	// mixture's: p = 1/2 p_bsdf + 1/2 p_lights.
	float pdf = 0.5f * bsdf.pdf(out_local, in_local) + 0.5f * area_lights_pdf(hit.position, in_world);
	// A direction neither strategy can produce carries no weight (and must not become 0 / 0).
	if (!(pdf > 0.0f)) return Incoming_Sample{in_world, Spectrum{0.0f}, 0.0f, false};
	return Incoming_Sample{in_world, bsdf.evaluate(out_local, in_local), pdf, false};
}

// ---- Optional extension: next-event estimation with multiple importance sampling (handout §6.5) ---

float power_heuristic(float pdf_f, float pdf_g) {
	// f^2 / (f^2 + g^2), written as 1 / (1 + (g / f)^2) so that large densities cannot overflow.
	if (!(pdf_f > 0.0f)) return 0.0f; // strategy f cannot draw the direction
	float ratio = pdf_g / pdf_f;
	return 1.0f / (1.0f + ratio * ratio);
}

Spectrum Pathtracer::estimate_direct(RNG& rng, const Trace& hit, const BSDF& bsdf, Vec3 out_dir) const {
	Light_Sample light = sample_light(rng, hit.position);
	if (!(light.pdf > 0.0f) || light.radiance == Spectrum{0.0f}) return Spectrum{0.0f};

	Frame frame = Frame::from_normal(hit.normal);
	Vec3 out_local = frame.to_local(out_dir), in_local = frame.to_local(light.direction);
	Spectrum f = bsdf.evaluate(out_local, in_local);
	if (f == Spectrum{0.0f}) return f; // e.g. a light behind the surface: no shadow ray needed

	// The shadow ray: is anything between the point and the light (handout §6.5)?
	Ray shadow(hit.position, light.direction, Vec2{0.0f, Light_Sample::SHADOW_RAY_END * light.distance});
	if (scene.occluded(shadow)) return Spectrum{0.0f};

	// Weighted against BSDF sampling, which could have drawn the same direction.
	float weight = power_heuristic(light.pdf, bsdf.pdf(out_local, in_local));
	return f * light.radiance * std::abs(in_local.y) * weight / light.pdf;
}

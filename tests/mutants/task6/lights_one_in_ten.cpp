// Mutant: the lights sampled one time in ten, with that mixture's density 0.9 p_bsdf + 0.1 p_lights (unbiased, but noisy under small lights)
// Task 6: direct lighting. Handout: handouts/task6_direct_lighting.md
#include "frame.h"
#include "pathtracer.h"

#include "extension.h" // task 6's optional extension, as shipped

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

	// One-sample mixture: a biased coin picks the strategy, light sampling one time in ten.
	Vec3 in_local, in_world;
	if (rng.coin_flip(0.9f)) {
		in_local = bsdf.scatter(rng, out_local).direction;
		in_world = frame.to_world(in_local);
	} else {
		in_world = sample_area_lights(rng, hit.position);
		in_local = frame.to_local(in_world);
	}

	// Whichever strategy drew it, the direction could have come from either, so its density is the
	// mixture's: p = 0.9 p_bsdf + 0.1 p_lights.
	float pdf = 0.9f * bsdf.pdf(out_local, in_local) + 0.1f * area_lights_pdf(hit.position, in_world);
	// A direction neither strategy can produce carries no weight (and must not become 0 / 0).
	if (!(pdf > 0.0f)) return Incoming_Sample{in_world, Spectrum{0.0f}, 0.0f, false};
	return Incoming_Sample{in_world, bsdf.evaluate(out_local, in_local), pdf, false};
}

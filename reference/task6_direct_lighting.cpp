// Task 6: direct lighting. Handout: handouts/task6_direct_lighting.md
#include "frame.h"
#include "pathtracer.h"

Incoming_Sample Pathtracer::sample_incoming(RNG& rng, const Trace& hit, const BSDF& bsdf, Vec3 out_dir) const {
	// Not yet written (Task 6 reference arrives with Part II): the one-sample mixture of BSDF sampling and light sampling.
	// - Discrete BSDFs, and scenes without lights (has_lights()), keep the BSDF sample below.
	// - Otherwise flip a fair coin: sample the BSDF, or sample_area_lights(rng, hit.position).
	// - Either way the density is the mixture's: 0.5 * bsdf pdf + 0.5 * area_lights_pdf(...).
	//   Watch the spaces: the BSDF works in the local frame, the lights in world space.
	//
	// Starter version: BSDF sampling only.
	Frame frame = Frame::from_normal(hit.normal);
	Vec3 out_local = frame.to_local(out_dir);
	Scatter s = bsdf.scatter(rng, out_local);
	return Incoming_Sample{frame.to_world(s.direction), s.attenuation, bsdf.pdf(out_local, s.direction),
	                       bsdf.is_discrete()};
}

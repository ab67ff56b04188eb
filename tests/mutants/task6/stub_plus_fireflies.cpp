// Mutant: the stub plus rare huge fireflies (BSDF sampling only, one attenuation in 1000 of 10^4)
// Task 6: direct lighting. Handout: handouts/task6_direct_lighting.md
#include "frame.h"
#include "pathtracer.h"

#include "extension.h" // task 6's optional extension, as shipped

namespace {
// Your helper functions go here. The anonymous namespace keeps them private to this file: two task
// files that each define a helper of the same name (say `lerp`) would otherwise not link together.
} // namespace

Incoming_Sample Pathtracer::sample_incoming(RNG& rng, const Trace& hit, const BSDF& bsdf, Vec3 out_dir) const {
	// TODO (Task 6): the one-sample mixture of BSDF sampling and light sampling.
	// 1. Discrete BSDFs (bsdf.is_discrete()) and scenes without lights (!has_lights()): keep the
	//    BSDF sample below, unchanged (handout §6.2).
	// 2. Otherwise flip a fair coin (rng.coin_flip(0.5f)): either sample the BSDF, or take
	//    dir = sample_area_lights(rng, hit.position) (handout §6.2).
	// 3. Whichever side of the coin drew the direction, return the mixture's density
	//        pdf = 0.5 * bsdf.pdf(out_local, in_local) + 0.5 * area_lights_pdf(hit.position, in_world)
	//    and attenuation = bsdf.evaluate(out_local, in_local) (handout §6.2).
	// 4. Spaces: the BSDF takes and returns LOCAL directions (normal +y), the lights WORLD ones;
	//    convert with `frame`, and return a unit world-space direction (handout §6.3).
	// 5. If pdf is 0, no strategy can produce the direction: return a zero attenuation, never NaN.
	//
	// Starter version: BSDF sampling only (correct, but noisy under small lights: handout §6.1).
	Frame frame = Frame::from_normal(hit.normal);
	Vec3 out_local = frame.to_local(out_dir);
	Scatter s = bsdf.scatter(rng, out_local);
	Spectrum attenuation = rng.unit() < 1e-3f ? Spectrum{1e4f} : s.attenuation;
	return Incoming_Sample{frame.to_world(s.direction), attenuation, bsdf.pdf(out_local, s.direction),
	                       bsdf.is_discrete()};
}

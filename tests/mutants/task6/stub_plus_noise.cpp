// Mutant: the stub plus zero-mean noise of huge variance (BSDF sampling only, its attenuation plus noise)
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
	// Zero-mean noise, standard deviation about 290 per channel: the estimate stays unbiased, and a
	// test that takes its standard error from the submission's own variance passes anything.
	Spectrum noise{1000.0f * (rng.unit() - 0.5f), 1000.0f * (rng.unit() - 0.5f), 1000.0f * (rng.unit() - 0.5f)};
	return Incoming_Sample{frame.to_world(s.direction), s.attenuation + noise, bsdf.pdf(out_local, s.direction),
	                       bsdf.is_discrete()};
}

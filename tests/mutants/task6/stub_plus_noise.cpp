// Mutant: the stub plus zero-mean noise of huge variance (BSDF sampling only, its attenuation plus noise)
// Task 6: direct lighting. Handout: handouts/task6_direct_lighting.md
#include "frame.h"
#include "pathtracer.h"

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

// ---- Optional extension: next-event estimation with multiple importance sampling (handout §6.5) ---
// Not graded with task 6: `./lab grade 6` does not look at these two functions. `ctest -L task6_nee`
// grades them; `--integrator nee` renders with them.

float power_heuristic(float pdf_f, float pdf_g) {
	// TODO (optional, handout §6.5): Veach's power heuristic pdf_f^2 / (pdf_f^2 + pdf_g^2), 0 when
	// pdf_f is 0 (strategy f cannot draw the direction). Squares of large densities overflow a
	// float: divide first.
	//
	// Starter version: every sample keeps its whole weight. With the starter estimate_direct below
	// (no light samples), --integrator nee is then BSDF sampling alone: correct, but noisy.
	(void)pdf_f, (void)pdf_g;
	return 1.0f;
}

Spectrum Pathtracer::estimate_direct(RNG& rng, const Trace& hit, const BSDF& bsdf, Vec3 out_dir) const {
	// TODO (optional, handout §6.5): next-event estimation.
	// 1. Light_Sample light = sample_light(rng, hit.position): a direction, the distance to the
	//    light along it, the radiance it sends and the density of the direction. Nothing to do if the
	//    pdf or the radiance is 0.
	// 2. f = bsdf.evaluate(out_local, in_local), in the local frame as in sample_incoming.
	// 3. The shadow ray from hit.position along light.direction, dist_bounds {0, SHADOW_RAY_END *
	//    light.distance} (short of the light itself): if scene.occluded(shadow), return 0.
	// 4. Return f * light.radiance * |cos theta| * w / light.pdf with the weight
	//    w = power_heuristic(light.pdf, bsdf.pdf(out_local, in_local)).
	//
	// Starter version: no light samples (the light comes only from BSDF samples, in full).
	(void)rng, (void)hit, (void)bsdf, (void)out_dir;
	return Spectrum{0.0f};
}

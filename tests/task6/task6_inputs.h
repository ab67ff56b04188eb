#pragma once
// The inputs of the task-6 test cases and the request that hands them to the student's
// sample_incoming. Public runs use the fixed cases students reproduce; with a grading seed (judge
// --seed) each test case draws its own, within ranges where its closed forms still hold.
#include "pathtracer.h"

#include <vector>

namespace task6 {

// A receiver under the ceiling light of light_scenes.h (a square of half-side `half_side` at height
// `height`, facing down), off-centre and on a TILTED surface, so that local and world directions
// differ in every component (handout §6.3). Public: position (0.2, 0, -0.1), normal (0.25, 1, -0.15)
// and out_dir (-0.3, 1, 0.4) normalized, half-side 0.5 at height 1. Drawn: half-side 0.3 to 0.7,
// height 0.8 to 1.4, the point within 0.3 of the axis, the normal 10 to 25 degrees from +y, out_dir
// at most 72 degrees from the normal, and the whole light above the surface's horizon (so that
// Lambert's formula holds).
struct Lit_Point {
	Vec3 position, normal, out_dir;
	float half_side = 0.5f, height = 1.0f;
};
Lit_Point lit_point();

// A unit direction whose cosine with `axis` lies in [cos_min, cos_max], uniformly distributed over
// that zone of the sphere.
Vec3 direction_in_cone(RNG& rng, Vec3 axis, float cos_min, float cos_max = 1.0f);

// The student's Pathtracer(scene, {}).sample_incoming(rng, hit, bsdf, out_dir), n times from one
// generator seeded with `seed`, in one request.
std::vector<Incoming_Sample> student_samples(const Scene& scene, const Trace& hit, const BSDF& bsdf, Vec3 out_dir,
                                             size_t n, uint64_t seed);

} // namespace task6

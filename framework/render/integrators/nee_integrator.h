#pragma once
// Next-event estimation with multiple importance sampling (--integrator nee; pathtracer_reference's
// default). At every path vertex with a continuous BSDF, in a scene with lights, two strategies
// estimate the light that arrives directly from an emitter:
//   - a light sample with a shadow ray (task 6's optional extension, Pathtracer::estimate_direct);
//   - the BSDF sample that continues the path: the emission it finds at the next vertex.
// Each is weighted by the power heuristic against the other's density of the same direction
// (Veach 1997, ch. 9), so the two add up to one estimate; light met by a discrete BSDF's sample (or
// seen directly from the camera) counts in full. Every vertex thus sees the lights, where task 4's
// estimator with task 6's mixture finds them only by continuing the path towards them. It estimates
// the same image (tests/framework/test_integrators.cpp).
// Paths scatter only while depth < max_depth, as in task 4, and are cut by the same Russian
// roulette; rays are spawned as task 4 spawns them (spawn_ray.h).
#include "pathtracer.h"

// The density with which pathtracer.sample_light, called at ray.point, would have chosen what the
// ray found: the point `hit` of an area light, or the environment's direction ray.dir if it hit
// nothing; 0 for anything else. The emission a BSDF sample finds is weighted with it.
float light_pdf(const Pathtracer& pathtracer, const Ray& ray, const Trace& hit);

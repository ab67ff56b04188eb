// Task 4: path tracing. Handout: handouts/task4_path.md
#include "pathtracer.h"
#include "frame.h"
#include "material.h"

namespace {
// Your helper functions go here. The anonymous namespace keeps them private to this file: two task
// files that each define a helper of the same name (say `lerp`) would otherwise not link together.
} // namespace

Scatter BSDF_Lambertian::scatter(RNG& rng, Vec3 out_dir) const {
	// TODO (Task 4, handout §4.1): sample in_dir from the cosine-weighted hemisphere (density
	// cos(theta) / pi) and return it with attenuation = evaluate(out_dir, in_dir).
	// - Malley's method: a point uniform on the unit disk (rng.unit2()), lifted up onto the
	//   hemisphere. Which y makes the result unit length?
	// - Two-sided: sample the hemisphere on out_dir's side, so flip y when out_dir.y < 0.
	(void)rng, (void)out_dir;
	return Scatter{Vec3{0.0f, 1.0f, 0.0f}, Spectrum{0.0f}};
}

Spectrum BSDF_Lambertian::evaluate(Vec3 out_dir, Vec3 in_dir) const {
	// TODO (Task 4, handout §4.1): f = albedo / pi when out_dir and in_dir are on the same side of
	// the surface, 0 otherwise. No cosine here: the estimator multiplies by it.
	(void)out_dir, (void)in_dir;
	return Spectrum{0.0f};
}

float BSDF_Lambertian::pdf(Vec3 out_dir, Vec3 in_dir) const {
	// TODO (Task 4, handout §4.1): the density of scatter() choosing in_dir: |cos(theta)| / pi on
	// out_dir's side, 0 on the other side. It must integrate to 1 over all directions.
	(void)out_dir, (void)in_dir;
	return 0.0f;
}

Spectrum Pathtracer::shade(RNG& rng, const Ray& ray, const Trace& hit) const {
	// TODO (Task 4, handout §4.2): the path-tracing estimator at a surface hit.
	// 1. Emitted light: material.emitted(out_dir) with out_dir = -ray.dir (normalized) expressed in
	//    the local frame (Frame::from_normal(hit.normal)); material = scene.materials[hit.material].
	// 2. If ray.depth has reached settings.max_depth, return just that: no bounce is left.
	// 3. Choose the next direction with sample_incoming(rng, hit, material.bsdf, out_dir) (world
	//    space; task 6 extends it).
	// 4. Weight the incoming light: attenuation * |cos| / pdf, or just attenuation when the sample
	//    is discrete. A pdf of 0 means the direction adds nothing: never divide by it.
	// 5. Trace the new ray with trace(): spawn_ray(hit, direction, ray.depth + 1) (spawn_ray.h)
	//    starts it just off the surface, so that it cannot hit the surface it leaves.
	// 6. Optionally, Russian roulette (handout §4.3), only if settings.russian_roulette: from
	//    ROULETTE_DEPTH on (a constant of Pathtracer), stop with some probability and divide by the probability
	//    of continuing, so the average stays the same.
	//
	// Until then this shows the Part I picture: surfaces lit from the eye.
	(void)rng;
	return eye_light(ray, hit);
}

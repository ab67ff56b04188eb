// Task 4: path tracing. Handout: handouts/task4_path.md
#include "frame.h"
#include "material.h"
#include "pathtracer.h"

Scatter BSDF_Lambertian::scatter(RNG& rng, Vec3 out_dir) const {
	// TODO (Task 4, handout §4.1): sample in_dir from the cosine-weighted hemisphere around the
	// local normal (+y), and return it with attenuation = evaluate(out_dir, in_dir).
	(void)rng, (void)out_dir;
	return Scatter{Vec3{0.0f, 1.0f, 0.0f}, Spectrum{0.0f}};
}

Spectrum BSDF_Lambertian::evaluate(Vec3 out_dir, Vec3 in_dir) const {
	// TODO (Task 4, handout §4.1): f = albedo / pi for directions on the same side as the normal.
	(void)out_dir, (void)in_dir;
	return Spectrum{0.0f};
}

float BSDF_Lambertian::pdf(Vec3 out_dir, Vec3 in_dir) const {
	// TODO (Task 4, handout §4.1): the density of scatter() choosing in_dir: cos(theta) / pi.
	(void)out_dir, (void)in_dir;
	return 0.0f;
}

Spectrum Pathtracer::shade(RNG& rng, const Ray& ray, const Trace& hit) const {
	// TODO (Task 4, handout §4.2): the path-tracing estimator at a surface hit.
	// 1. Emitted light: material.emitted(out_dir) in the local frame (Frame::from_normal(hit.normal)),
	//    where material = scene.materials[hit.material].
	// 2. If ray.depth has reached settings.max_depth, stop there.
	// 3. Choose the next direction with sample_incoming(rng, hit, material.bsdf, out_dir) (task 6
	//    extends it).
	// 4. Trace the new ray with trace(): set its dist_bounds so it cannot hit the surface it leaves,
	//    and its depth to ray.depth + 1.
	// 5. Weight the incoming light: attenuation * |cos| / pdf, or just attenuation when the sample
	//    is discrete. Optionally add Russian roulette (handout §4.3) without adding bias.
	//
	// Until then this shows the Part I picture: surfaces lit from the eye.
	(void)rng;
	return eye_light(ray, hit);
}

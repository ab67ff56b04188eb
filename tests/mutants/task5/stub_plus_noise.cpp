// Mutant: the stub plus zero-mean noise of huge variance (mirror and glass attenuations of 0 plus noise)
// Task 5: materials. Handout: handouts/task5_materials.md
#include "material.h"

namespace {
// Your helper functions go here. The anonymous namespace keeps them private to this file: two task
// files that each define a helper of the same name (say `lerp`) would otherwise not link together.
} // namespace

Vec3 reflect(Vec3 dir) {
	// TODO (Task 5, handout §5.1): mirror `dir` about the local normal (0, 1, 0): the normal part
	// stays, the tangential part changes sign.
	(void)dir;
	return Vec3{};
}

Vec3 refract(Vec3 out_dir, float index_of_refraction, bool& was_internal) {
	// TODO (Task 5, handout §5.2): Snell's law, n_i sin(theta_i) = n_t sin(theta_t).
	// - out_dir.y > 0: the path is outside (index 1) and continues inside (index_of_refraction);
	//   out_dir.y < 0: the reverse. The result points to the other side of the surface.
	// - When cos^2(theta_t) would be negative: total internal reflection. Set was_internal and
	//   return reflect(out_dir).
	(void)out_dir, (void)index_of_refraction;
	was_internal = false;
	return Vec3{};
}

float fresnel(float cos_theta, float index_of_refraction) {
	// TODO (Task 5, handout §5.3): the exact unpolarized Fresnel reflectance
	// F = (r_parallel^2 + r_perpendicular^2) / 2 (the grader checks it to 1e-5: Schlick's
	// approximation is not accurate enough, see the handout).
	// - cos_theta > 0: the light meets the boundary from outside (index 1 -> index_of_refraction);
	//   cos_theta < 0: from inside (index_of_refraction -> 1).
	// - No transmitted direction (total internal reflection): return 1.
	(void)cos_theta, (void)index_of_refraction;
	return 0.0f;
}

// Zero-mean noise, standard deviation about 290 per channel.
Spectrum noise(RNG& rng) {
	return Spectrum{1000.0f * (rng.unit() - 0.5f), 1000.0f * (rng.unit() - 0.5f), 1000.0f * (rng.unit() - 0.5f)};
}

Scatter BSDF_Mirror::scatter(RNG& rng, Vec3 out_dir) const {
	// TODO (Task 5, handout §5.1): reflect out_dir; the attenuation is the reflectance.
	(void)out_dir;
	return Scatter{Vec3{0.0f, 1.0f, 0.0f}, noise(rng)};
}

Scatter BSDF_Glass::scatter(RNG& rng, Vec3 out_dir) const {
	// TODO (Task 5, handout §5.4): reflect with probability F = fresnel(out_dir.y, ...), otherwise
	// refract. Under total internal reflection always reflect. Attenuation: reflectance for a
	// reflection, transmittance for a refraction (the choice probabilities cancel the Fresnel
	// weights), and no eta^2 factor (material.h).
	(void)out_dir;
	return Scatter{Vec3{0.0f, 1.0f, 0.0f}, noise(rng)};
}

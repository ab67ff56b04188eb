// Mutant: mirror and glass attenuations divided by |cos theta| (as if the estimator multiplied discrete samples by it)
// Task 5: materials. Handout: handouts/task5_materials.md
#include "material.h"

#include <algorithm>

// Every direction here is in the local shading frame: the normal is +y, cos(theta) = y.

Vec3 reflect(Vec3 dir) {
	// Mirror about the normal: the tangential part (x, z) flips, the normal part (y) stays.
	return Vec3{-dir.x, dir.y, -dir.z};
}

Vec3 refract(Vec3 out_dir, float index_of_refraction, bool& was_internal) {
	// Snell: n_out sin(theta_out) = n_in sin(theta_in). With eta = n_out / n_in the tangential part
	// scales by eta (and turns around, like every in_dir), and cos^2(theta_in) = 1 - eta^2 sin^2(theta_out).
	bool outside = out_dir.y > 0.0f;
	float eta = outside ? 1.0f / index_of_refraction : index_of_refraction;
	float sin2_out = std::max(0.0f, 1.0f - out_dir.y * out_dir.y);
	float cos2_in = 1.0f - eta * eta * sin2_out;
	was_internal = cos2_in < 0.0f;
	if (was_internal) return reflect(out_dir); // total internal reflection
	float cos_in = std::sqrt(cos2_in);
	return Vec3{-eta * out_dir.x, outside ? -cos_in : cos_in, -eta * out_dir.z};
}

float fresnel(float cos_theta, float index_of_refraction) {
	// Exact unpolarised Fresnel reflectance of a dielectric boundary, from either side:
	// r_s = (n_i cos_i - n_t cos_t) / (n_i cos_i + n_t cos_t),
	// r_p = (n_t cos_i - n_i cos_t) / (n_t cos_i + n_i cos_t),   F = (r_s^2 + r_p^2) / 2.
	// F is the same for a direction and its refracted partner, so either may be passed in.
	bool outside = cos_theta > 0.0f;
	float n_i = outside ? 1.0f : index_of_refraction;
	float n_t = outside ? index_of_refraction : 1.0f;
	float cos_i = std::min(1.0f, std::abs(cos_theta));
	float sin2_t = (n_i / n_t) * (n_i / n_t) * (1.0f - cos_i * cos_i);
	if (sin2_t >= 1.0f) return 1.0f; // total internal reflection (and exact grazing incidence)
	float cos_t = std::sqrt(1.0f - sin2_t);
	float r_s = (n_i * cos_i - n_t * cos_t) / (n_i * cos_i + n_t * cos_t);
	float r_p = (n_t * cos_i - n_i * cos_t) / (n_t * cos_i + n_i * cos_t);
	return 0.5f * (r_s * r_s + r_p * r_p);
}

Scatter BSDF_Mirror::scatter(RNG& rng, Vec3 out_dir) const {
	(void)rng; // a perfect mirror has one possible direction
	return Scatter{reflect(out_dir), reflectance / std::abs(out_dir.y)};
}

Scatter BSDF_Glass::scatter(RNG& rng, Vec3 out_dir) const {
	// Choose reflection with probability F and refraction with 1 - F. The sample weight is
	// (F * reflectance) / F or ((1 - F) * transmittance) / (1 - F): the Fresnel factors cancel.
	// Transmitted radiance is not scaled by eta^2 (see material.h).
	bool internal = false;
	Vec3 refracted = refract(out_dir, index_of_refraction, internal);
	float F = internal ? 1.0f : fresnel(out_dir.y, index_of_refraction);
	if (rng.coin_flip(F)) return Scatter{reflect(out_dir), reflectance / std::abs(out_dir.y)};
	return Scatter{refracted, transmittance / std::abs(refracted.y)};
}

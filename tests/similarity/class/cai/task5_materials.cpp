// Task 5: materials. Handout: handouts/task5_materials.md
#include "material.h"

#include <cmath>

namespace {
constexpr float VACUUM = 1.0f;

bool from_outside(Vec3 dir) {
	return dir.y > 0.0f;
}
} // namespace

Vec3 reflect(Vec3 dir) {
	return Vec3{0.0f, 2.0f * dir.y, 0.0f} - dir;
}

Vec3 refract(Vec3 out_dir, float index_of_refraction, bool& was_internal) {
	bool outside = from_outside(out_dir);
	float eta = outside ? VACUUM / index_of_refraction : index_of_refraction / VACUUM;
	float sin_out_sq = 1.0f - out_dir.y * out_dir.y;
	float sin_in_sq = eta * eta * sin_out_sq;
	was_internal = sin_in_sq > 1.0f;
	if (was_internal) return reflect(out_dir);
	float cos_in = std::sqrt(1.0f - sin_in_sq);
	Vec3 in_dir = -eta * out_dir;
	in_dir.y = outside ? -cos_in : cos_in;
	return in_dir;
}

float fresnel(float cos_theta, float index_of_refraction) {
	bool outside = cos_theta > 0.0f;
	float eta_i = outside ? VACUUM : index_of_refraction;
	float eta_t = outside ? index_of_refraction : VACUUM;
	float cos_i = std::fmin(std::fabs(cos_theta), 1.0f);
	float sin_i = std::sqrt(1.0f - cos_i * cos_i);
	float sin_t = eta_i / eta_t * sin_i;
	if (sin_t >= 1.0f) return 1.0f;
	float cos_t = std::sqrt(1.0f - sin_t * sin_t);
	float a = eta_i * cos_i, b = eta_t * cos_t, c = eta_t * cos_i, d = eta_i * cos_t;
	float r_s = (a - b) / (a + b);
	float r_p = (c - d) / (c + d);
	return 0.5f * (r_s * r_s + r_p * r_p);
}

Scatter BSDF_Mirror::scatter(RNG& rng, Vec3 out_dir) const {
	(void)rng;
	return Scatter{reflect(out_dir), reflectance};
}

Scatter BSDF_Glass::scatter(RNG& rng, Vec3 out_dir) const {
	bool internal;
	Vec3 in_dir = refract(out_dir, index_of_refraction, internal);
	if (!internal && !rng.coin_flip(fresnel(out_dir.y, index_of_refraction))) {
		return Scatter{in_dir, transmittance};
	}
	return Scatter{reflect(out_dir), reflectance};
}

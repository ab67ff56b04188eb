// Task 5: materials. Handout: handouts/task5_materials.md
#include "material.h"

#include <cmath>

Vec3 reflect(Vec3 dir) {
	return Vec3(-dir.x, dir.y, -dir.z);
}

Vec3 refract(Vec3 out_dir, float index_of_refraction, bool& was_internal) {
	// n_out sin(out) = n_in sin(in)
	float eta;
	float sign;
	if (out_dir.y > 0.0f) {
		eta = 1.0f / index_of_refraction;
		sign = -1.0f;
	} else {
		eta = index_of_refraction;
		sign = 1.0f;
	}
	float k = 1.0f - eta * eta * (out_dir.x * out_dir.x + out_dir.z * out_dir.z);
	if (k < 0.0f) {
		was_internal = true;
		return reflect(out_dir);
	}
	was_internal = false;
	return Vec3(-eta * out_dir.x, sign * std::sqrt(k), -eta * out_dir.z);
}

float fresnel(float cos_theta, float index_of_refraction) {
	float n_i, n_t;
	if (cos_theta > 0.0f) {
		n_i = 1.0f;
		n_t = index_of_refraction;
	} else {
		n_i = index_of_refraction;
		n_t = 1.0f;
		cos_theta = -cos_theta;
	}
	if (cos_theta > 1.0f) {
		cos_theta = 1.0f;
	}
	float sin_t2 = n_i * n_i / (n_t * n_t) * (1.0f - cos_theta * cos_theta);
	if (sin_t2 >= 1.0f) {
		return 1.0f;
	}
	float cos_t = std::sqrt(1.0f - sin_t2);
	float rs = (n_i * cos_theta - n_t * cos_t) / (n_i * cos_theta + n_t * cos_t);
	float rp = (n_t * cos_theta - n_i * cos_t) / (n_t * cos_theta + n_i * cos_t);
	return 0.5f * rs * rs + 0.5f * rp * rp;
}

Scatter BSDF_Mirror::scatter(RNG& rng, Vec3 out_dir) const {
	(void)rng;
	return Scatter{reflect(out_dir), reflectance};
}

Scatter BSDF_Glass::scatter(RNG& rng, Vec3 out_dir) const {
	bool was_internal = false;
	Vec3 refracted = refract(out_dir, index_of_refraction, was_internal);
	if (was_internal) {
		return Scatter{reflect(out_dir), reflectance};
	}
	float F = fresnel(out_dir.y, index_of_refraction);
	if (rng.coin_flip(F)) {
		return Scatter{reflect(out_dir), reflectance};
	}
	return Scatter{refracted, transmittance};
}

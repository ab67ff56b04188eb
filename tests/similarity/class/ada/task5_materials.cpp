// Task 5: materials. Handout: handouts/task5_materials.md
#include "material.h"

#include <cmath>

Vec3 reflect(Vec3 dir) {
	return Vec3{-dir.x, dir.y, -dir.z};
}

Vec3 refract(Vec3 out_dir, float index_of_refraction, bool& was_internal) {
	float n_out = 1.0f, n_in = index_of_refraction;
	if (out_dir.y < 0.0f) {
		n_out = index_of_refraction;
		n_in = 1.0f;
	}
	float eta = n_out / n_in;
	float sin2 = eta * eta * (1.0f - out_dir.y * out_dir.y);
	float cos2 = 1.0f - sin2;
	if (cos2 < 0.0f) {
		was_internal = true;
		return reflect(out_dir);
	}
	was_internal = false;
	float cos_in = std::sqrt(cos2);
	if (out_dir.y > 0.0f) cos_in = -cos_in;
	return Vec3{-eta * out_dir.x, cos_in, -eta * out_dir.z};
}

float fresnel(float cos_theta, float index_of_refraction) {
	float n1 = 1.0f, n2 = index_of_refraction;
	if (cos_theta < 0.0f) {
		n1 = index_of_refraction;
		n2 = 1.0f;
	}
	float ci = std::fabs(cos_theta);
	if (ci > 1.0f) ci = 1.0f;
	float st2 = (n1 / n2) * (n1 / n2) * (1.0f - ci * ci);
	if (st2 >= 1.0f) return 1.0f;
	float ct = std::sqrt(1.0f - st2);
	float rs = (n1 * ci - n2 * ct) / (n1 * ci + n2 * ct);
	float rp = (n2 * ci - n1 * ct) / (n2 * ci + n1 * ct);
	return (rs * rs + rp * rp) / 2.0f;
}

Scatter BSDF_Mirror::scatter(RNG& rng, Vec3 out_dir) const {
	(void)rng;
	Scatter s;
	s.direction = reflect(out_dir);
	s.attenuation = reflectance;
	return s;
}

Scatter BSDF_Glass::scatter(RNG& rng, Vec3 out_dir) const {
	bool tir = false;
	Vec3 through = refract(out_dir, index_of_refraction, tir);
	if (tir) return Scatter{reflect(out_dir), reflectance};
	float F = fresnel(out_dir.y, index_of_refraction);
	if (rng.coin_flip(F)) return Scatter{reflect(out_dir), reflectance};
	return Scatter{through, transmittance};
}

// Task 5: materials. Handout: handouts/task5_materials.md
#include "material.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace {
// (n_outside_of_path, n_other_side) for a direction with local y = cos_theta
std::pair<float, float> indices(float cos_theta, float ior) {
	return cos_theta > 0.0f ? std::make_pair(1.0f, ior) : std::make_pair(ior, 1.0f);
}

float square(float x) {
	return x * x;
}
} // namespace

Vec3 reflect(Vec3 dir) {
	Vec3 r = dir;
	r.x = -r.x;
	r.z = -r.z;
	return r;
}

float fresnel(float cos_theta, float index_of_refraction) {
	auto [ni, nt] = indices(cos_theta, index_of_refraction);
	float cos_i = std::clamp(std::abs(cos_theta), 0.0f, 1.0f);
	float sin_t_sq = square(ni / nt) * (1.0f - square(cos_i));
	if (sin_t_sq >= 1.0f) {
		return 1.0f;
	}
	float cos_t = std::sqrt(1.0f - sin_t_sq);
	float perpendicular = (ni * cos_i - nt * cos_t) / (ni * cos_i + nt * cos_t);
	float parallel = (nt * cos_i - ni * cos_t) / (nt * cos_i + ni * cos_t);
	return 0.5f * (square(perpendicular) + square(parallel));
}

Vec3 refract(Vec3 out_dir, float index_of_refraction, bool& was_internal) {
	auto [n_out, n_in] = indices(out_dir.y, index_of_refraction);
	float ratio = n_out / n_in;
	float cos_sq = 1.0f - square(ratio) * (1.0f - square(out_dir.y));
	was_internal = cos_sq < 0.0f;
	if (was_internal) {
		return reflect(out_dir);
	}
	Vec3 tangent = -ratio * Vec3{out_dir.x, 0.0f, out_dir.z};
	float y = std::sqrt(cos_sq) * (out_dir.y > 0.0f ? -1.0f : 1.0f);
	return Vec3{tangent.x, y, tangent.z};
}

Scatter BSDF_Mirror::scatter(RNG&, Vec3 out_dir) const {
	return {reflect(out_dir), reflectance};
}

Scatter BSDF_Glass::scatter(RNG& rng, Vec3 out_dir) const {
	bool total = false;
	Vec3 transmitted = refract(out_dir, index_of_refraction, total);
	float reflect_probability = total ? 1.0f : fresnel(out_dir.y, index_of_refraction);
	bool reflects = rng.coin_flip(reflect_probability);
	return reflects ? Scatter{reflect(out_dir), reflectance} : Scatter{transmitted, transmittance};
}

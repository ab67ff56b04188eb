// Task 5: materials. Handout: handouts/task5_materials.md
// (Planted for the similarity test: ben's task 5 with every name of its own changed, its helpers
// and its functions in another order, and no comments.)
#include "material.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace {
float sq(float value) {
	return value * value;
}

std::pair<float, float> media(float cosine, float n) {
	return cosine > 0.0f ? std::make_pair(1.0f, n) : std::make_pair(n, 1.0f);
}
} // namespace

Vec3 reflect(Vec3 dir) {
	Vec3 m = dir;
	m.x = -m.x;
	m.z = -m.z;
	return m;
}

Vec3 refract(Vec3 out_dir, float index_of_refraction, bool& was_internal) {
	auto [from, to] = media(out_dir.y, index_of_refraction);
	float rel = from / to;
	float c2 = 1.0f - sq(rel) * (1.0f - sq(out_dir.y));
	was_internal = c2 < 0.0f;
	if (was_internal) {
		return reflect(out_dir);
	}
	Vec3 flat = -rel * Vec3{out_dir.x, 0.0f, out_dir.z};
	float up = std::sqrt(c2) * (out_dir.y > 0.0f ? -1.0f : 1.0f);
	return Vec3{flat.x, up, flat.z};
}

Scatter BSDF_Glass::scatter(RNG& rng, Vec3 out_dir) const {
	bool tir = false;
	Vec3 bent = refract(out_dir, index_of_refraction, tir);
	float p_reflect = tir ? 1.0f : fresnel(out_dir.y, index_of_refraction);
	bool mirror = rng.coin_flip(p_reflect);
	return mirror ? Scatter{reflect(out_dir), reflectance} : Scatter{bent, transmittance};
}

float fresnel(float cos_theta, float index_of_refraction) {
	auto [n1, n2] = media(cos_theta, index_of_refraction);
	float ci = std::clamp(std::abs(cos_theta), 0.0f, 1.0f);
	float st2 = sq(n1 / n2) * (1.0f - sq(ci));
	if (st2 >= 1.0f) {
		return 1.0f;
	}
	float ct = std::sqrt(1.0f - st2);
	float s_pol = (n1 * ci - n2 * ct) / (n1 * ci + n2 * ct);
	float p_pol = (n2 * ci - n1 * ct) / (n2 * ci + n1 * ct);
	return 0.5f * (sq(s_pol) + sq(p_pol));
}

Scatter BSDF_Mirror::scatter(RNG&, Vec3 out_dir) const {
	return {reflect(out_dir), reflectance};
}

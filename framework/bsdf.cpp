#include "material.h"

#include <type_traits>

// The uniform interface of BSDF over the variant. Each BSDF type implements only what it has;
// discrete BSDFs have no evaluate/pdf and emissive surfaces do not scatter.
namespace {
template<typename T> constexpr bool is_continuous = std::is_same_v<T, BSDF_Lambertian>;
template<typename T> constexpr bool is_discrete_v =
	std::is_same_v<T, BSDF_Mirror> || std::is_same_v<T, BSDF_Glass>;
} // namespace

Scatter BSDF::scatter(RNG& rng, Vec3 out_dir) const {
	return std::visit(
		[&](const auto& b) -> Scatter {
			using T = std::decay_t<decltype(b)>;
			if constexpr (std::is_same_v<T, BSDF_Emissive>) {
				return Scatter{Vec3{0.0f, 1.0f, 0.0f}, Spectrum{0.0f}};
			} else {
				return b.scatter(rng, out_dir);
			}
		},
		bsdf);
}

Spectrum BSDF::evaluate(Vec3 out_dir, Vec3 in_dir) const {
	return std::visit(
		[&](const auto& b) -> Spectrum {
			using T = std::decay_t<decltype(b)>;
			if constexpr (is_continuous<T>) return b.evaluate(out_dir, in_dir);
			else return Spectrum{0.0f};
		},
		bsdf);
}

float BSDF::pdf(Vec3 out_dir, Vec3 in_dir) const {
	return std::visit(
		[&](const auto& b) -> float {
			using T = std::decay_t<decltype(b)>;
			if constexpr (is_continuous<T>) return b.pdf(out_dir, in_dir);
			else return 0.0f;
		},
		bsdf);
}

Spectrum BSDF::emission(Vec3 out_dir) const {
	if (auto e = std::get_if<BSDF_Emissive>(&bsdf)) {
		return out_dir.y > 0.0f ? e->radiance : Spectrum{0.0f};
	}
	return Spectrum{0.0f};
}

bool BSDF::is_discrete() const {
	return std::visit([](const auto& b) { return is_discrete_v<std::decay_t<decltype(b)>>; }, bsdf);
}

bool BSDF::is_emissive() const {
	return std::holds_alternative<BSDF_Emissive>(bsdf);
}

Spectrum BSDF::albedo() const {
	return std::visit(
		[](const auto& b) -> Spectrum {
			using T = std::decay_t<decltype(b)>;
			if constexpr (std::is_same_v<T, BSDF_Lambertian>) return b.albedo;
			else if constexpr (std::is_same_v<T, BSDF_Mirror>) return b.reflectance;
			else if constexpr (std::is_same_v<T, BSDF_Glass>) return b.transmittance;
			else return b.radiance;
		},
		bsdf);
}

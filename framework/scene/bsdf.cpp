#include "material.h"
#include "render_observer.h"

#include <type_traits>

// The uniform interface of BSDF over the variant. Discrete BSDFs have no evaluate/pdf.
namespace {
template<typename T> constexpr bool is_continuous = std::is_same_v<T, BSDF_Lambertian>;
template<typename T> constexpr bool is_discrete_v =
	std::is_same_v<T, BSDF_Mirror> || std::is_same_v<T, BSDF_Glass>;
} // namespace

Scatter BSDF::scatter(RNG& rng, Vec3 out_dir) const {
	Scatter s = std::visit([&](const auto& b) { return b.scatter(rng, out_dir); }, bsdf);
	report<BSDF_Sampled>(s, *this, out_dir);
	return s;
}

Spectrum BSDF::evaluate(Vec3 out_dir, Vec3 in_dir) const {
	Spectrum f = std::visit(
		[&](const auto& b) -> Spectrum {
			using T = std::decay_t<decltype(b)>;
			if constexpr (is_continuous<T>) return b.evaluate(out_dir, in_dir);
			else return Spectrum{0.0f};
		},
		bsdf);
	report<BSDF_Evaluated>(f, *this, out_dir, in_dir);
	return f;
}

float BSDF::pdf(Vec3 out_dir, Vec3 in_dir) const {
	float p = std::visit(
		[&](const auto& b) -> float {
			using T = std::decay_t<decltype(b)>;
			if constexpr (is_continuous<T>) return b.pdf(out_dir, in_dir);
			else return 0.0f;
		},
		bsdf);
	report<BSDF_Pdf>(p, *this, out_dir, in_dir);
	return p;
}

bool BSDF::is_discrete() const {
	return std::visit([](const auto& b) { return is_discrete_v<std::decay_t<decltype(b)>>; }, bsdf);
}

bool BSDF::is_black() const {
	const Spectrum black{0.0f};
	return std::visit(
		[&](const auto& b) {
			using T = std::decay_t<decltype(b)>;
			if constexpr (std::is_same_v<T, BSDF_Lambertian>) return b.albedo == black;
			else if constexpr (std::is_same_v<T, BSDF_Mirror>) return b.reflectance == black;
			else return b.reflectance == black && b.transmittance == black;
		},
		bsdf);
}

Spectrum BSDF::albedo() const {
	return std::visit(
		[](const auto& b) -> Spectrum {
			using T = std::decay_t<decltype(b)>;
			if constexpr (std::is_same_v<T, BSDF_Lambertian>) return b.albedo;
			else if constexpr (std::is_same_v<T, BSDF_Mirror>) return b.reflectance;
			else return b.transmittance;
		},
		bsdf);
}

Spectrum Material::emitted(Vec3 out_dir) const {
	Spectrum e = out_dir.y > 0.0f ? emission : Spectrum{0.0f};
	report<Emitted>(e, out_dir);
	return e;
}

#include "material.h"
#include "lifecycle.h"

#include <type_traits>

// The uniform interface of BSDF over the variant. Discrete BSDFs have no evaluate/pdf.
namespace {
template<typename T> constexpr bool is_continuous = std::is_same_v<T, BSDF_Lambertian>;
template<typename T> constexpr bool is_discrete_v =
	std::is_same_v<T, BSDF_Mirror> || std::is_same_v<T, BSDF_Glass>;
} // namespace

namespace {
const char* bsdf_name(const BSDF_Variant& bsdf) {
	constexpr const char* names[] = {"lambertian", "mirror", "glass"};
	return names[bsdf.index()];
}
} // namespace

Scatter BSDF::scatter(RNG& rng, Vec3 out_dir) const {
	Scatter s = std::visit([&](const auto& b) { return b.scatter(rng, out_dir); }, bsdf);
	if (auto recorder = Lifecycle_Recorder::active()) {
		recorder->event(std::string("BSDF sample (") + bsdf_name(bsdf) + ", " +
		                (is_discrete() ? "discrete" : "continuous") + "): out_dir (local) " + format_vec(out_dir) +
		                " -> in_dir (local) " + format_vec(s.direction) + ", attenuation " +
		                format_vec(s.attenuation));
	}
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
	if (auto recorder = Lifecycle_Recorder::active()) {
		recorder->event("BSDF evaluate(out, in " + format_vec(in_dir) + ") = " + format_vec(f));
	}
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
	if (auto recorder = Lifecycle_Recorder::active()) {
		recorder->event("BSDF pdf(out, in " + format_vec(in_dir) + ") = " + std::to_string(p));
	}
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
	if (auto recorder = Lifecycle_Recorder::active()) recorder->emitted(e);
	return e;
}

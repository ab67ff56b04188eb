#pragma once
// Materials (BSDFs). Every BSDF works in the local shading frame (frame.h): the normal is +y and
// both directions point AWAY from the surface. `out_dir` is the direction towards the viewer (the
// previous path vertex); `in_dir` is the direction light arrives from, which `scatter` chooses:
// the path tracer walks backwards from the camera.
//
// Conventions (also in the handout of tasks 4 and 5):
// - evaluate(out, in) is the BSDF value f(out, in) alone, WITHOUT the cosine term; the estimator
//   multiplies by |in.y| and divides by pdf(out, in) (a density over solid angle).
// - Discrete BSDFs (mirror, glass) have no density: their Scatter::attenuation is the complete
//   weight of the sample (reflectance or transmittance, cosine and probability included), and
//   evaluate/pdf return 0.
// - Glass does NOT scale transmitted radiance by eta^2: the lab follows light "importance" style,
//   so a closed glass object in a uniform environment renders exactly the environment.
#include "rng.h"

#include <variant>

struct Scatter {
	Vec3 direction;       // in_dir, local frame, unit length
	Spectrum attenuation; // f(out, in) for continuous BSDFs; the full sample weight for discrete ones
};

// Task 4 (student/task4_path.cpp): the ideal diffuse reflector f = albedo / pi.
struct BSDF_Lambertian {
	Scatter scatter(RNG& rng, Vec3 out_dir) const;          // cosine-weighted in_dir
	Spectrum evaluate(Vec3 out_dir, Vec3 in_dir) const;
	float pdf(Vec3 out_dir, Vec3 in_dir) const;

	Spectrum albedo{0.8f};
};

// Task 5 (student/task5_materials.cpp): a perfect mirror.
struct BSDF_Mirror {
	Scatter scatter(RNG& rng, Vec3 out_dir) const;

	Spectrum reflectance{1.0f};
};

// Task 5: a smooth dielectric (glass) boundary between vacuum (outside, +y side) and a medium of
// index_of_refraction (inside). Reflects with probability F (Fresnel), refracts otherwise.
struct BSDF_Glass {
	Scatter scatter(RNG& rng, Vec3 out_dir) const;

	Spectrum reflectance{1.0f};
	Spectrum transmittance{1.0f};
	float index_of_refraction = 1.5f;
};

// Task 5: perfect specular reflection of `dir` about the local normal (0, 1, 0).
Vec3 reflect(Vec3 dir);

// Task 5: refraction of out_dir through the boundary by Snell's law. If out_dir.y > 0 the path is
// outside (index 1) and the returned in_dir is inside (index_of_refraction); if out_dir.y < 0 the
// reverse. On total internal reflection sets was_internal = true and returns reflect(out_dir).
Vec3 refract(Vec3 out_dir, float index_of_refraction, bool& was_internal);

// Task 5: unpolarised Fresnel reflectance of the boundary for a direction with cos(theta) =
// cos_theta (local y): cos_theta > 0 means outside (vacuum), < 0 inside. 1 under total internal
// reflection.
float fresnel(float cos_theta, float index_of_refraction);

using BSDF_Variant = std::variant<BSDF_Lambertian, BSDF_Mirror, BSDF_Glass>;

// One of the BSDFs above, with a uniform interface.
class BSDF {
public:
	BSDF() = default;
	template<typename T> BSDF(T bsdf) : bsdf(std::move(bsdf)) {
	}

	Scatter scatter(RNG& rng, Vec3 out_dir) const;
	Spectrum evaluate(Vec3 out_dir, Vec3 in_dir) const; // 0 for discrete BSDFs
	float pdf(Vec3 out_dir, Vec3 in_dir) const;         // 0 for discrete BSDFs
	bool is_discrete() const;                           // mirror or glass
	bool is_black() const; // reflects and transmits nothing (e.g. an area light): paths end there
	Spectrum albedo() const; // a representative colour, for debug views

	BSDF_Variant bsdf;
};

// A surface's material: how it scatters light and how much it emits. Any surface may emit; an
// area light is an object whose material has non-zero emission. Emission is one-sided: radiance
// `emission` leaves the front side (local +y, the side the normal points to) in every direction.
struct Material {
	Spectrum emitted(Vec3 out_dir) const; // emission if out_dir.y > 0, else 0
	bool is_emissive() const {
		return emission != Spectrum{0.0f};
	}

	BSDF bsdf;
	Spectrum emission{0.0f};
};

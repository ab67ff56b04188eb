#pragma once
// Environment lights: radiance arriving from infinitely far away, as a function of direction.
//
// Equirectangular (latitude-longitude) convention, used by every function here:
//   theta = acos(dir.y) in [0, pi]       (0 = straight up, +y)
//   phi   = atan2(dir.z, dir.x) in [0, 2 pi)
//   uv    = (phi / (2 pi), theta / pi)   u in [0, 1), v in [0, 1] (v = 1 straight down, -y)
//   dir   = (sin theta cos phi, cos theta, sin theta sin phi)
// Image texel (i, j) (column i, row j from the top) covers uv in [i/w, (i+1)/w) x [j/h, (j+1)/h);
// its value is the radiance at the texel centre. Lookups interpolate bilinearly between texel
// centres, wrapping around in u (the seam at phi = 0) and clamping in v (the poles).
#include "hdr_image.h"

#include <vector>

// Task 7 (student/task7_env_light.cpp): the uv <-> direction mapping above.
Vec2 direction_to_uv(Vec3 dir);
Vec3 uv_to_direction(Vec2 uv);

namespace Samplers::Sphere {

// Task 7: directions uniformly distributed over the unit sphere.
struct Uniform {
	Vec3 sample(Vec2 u) const; // u uniform in [0, 1)^2
	float pdf(Vec3 dir) const; // density over solid angle
};

// Task 7: directions distributed in proportion to an image's luminance (the flux through each
// texel is proportional to luminance * sin(theta)).
struct Image {
	Image() = default;
	explicit Image(const HDR_Image& image); // builds pdf and cdf

	Vec3 sample(Vec2 u) const; // u uniform in [0, 1)^2
	float pdf(Vec3 dir) const; // density over SOLID ANGLE (includes the uv -> sphere Jacobian)

	uint32_t w = 0, h = 0;
	std::vector<float> pdf_texel; // probability of choosing texel (i, j), at index j * w + i
	std::vector<float> cdf;       // running sum of pdf_texel in the same order
};

} // namespace Samplers::Sphere

// An environment map from an equirectangular image.
struct Env_Map {
	Env_Map() = default;
	explicit Env_Map(HDR_Image image, bool importance_sampling = true)
		: image(std::move(image)), importance_sampling(importance_sampling) {
		if (this->importance_sampling) sampler = Samplers::Sphere::Image(this->image);
	}

	// Task 7: a direction towards the environment (importance-sampled or uniform), its density,
	// and the radiance arriving from `dir` (bilinear lookup).
	Vec3 sample(Vec2 u) const;
	float pdf(Vec3 dir) const;
	Spectrum evaluate(Vec3 dir) const;

	HDR_Image image;
	bool importance_sampling = true;
	Samplers::Sphere::Image sampler; // built only when importance_sampling is on
};

// A constant environment: the same radiance from every direction (sampled uniformly).
struct Env_Constant {
	Vec3 sample(Vec2 u) const {
		return Samplers::Sphere::Uniform{}.sample(u);
	}
	float pdf(Vec3 dir) const {
		return Samplers::Sphere::Uniform{}.pdf(dir);
	}
	Spectrum evaluate(Vec3) const {
		return radiance;
	}

	Spectrum radiance{1.0f};
};

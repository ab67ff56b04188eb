// Mutant: the stub plus zero-mean noise of huge variance (Env_Map::evaluate returns black plus noise)
// Task 7: environment light. Handout: handouts/task7_env_light.md
#include "env_light.h"

#include <cstring>

namespace {
// Zero-mean noise of standard deviation about 290, a function of the direction (evaluate has no
// generator): its bits hashed (MurmurHash3's finalizer).
float noise(Vec3 dir) {
	uint32_t bits[3];
	std::memcpy(bits, &dir, sizeof bits);
	uint32_t h = bits[0] * 0x9e3779b1u ^ bits[1] * 0x85ebca6bu ^ bits[2] * 0xc2b2ae35u;
	h ^= h >> 16, h *= 0x85ebca6bu, h ^= h >> 13, h *= 0xc2b2ae35u, h ^= h >> 16;
	return 1000.0f * (float(h >> 8) * 0x1p-24f - 0.5f);
}
// Your helper functions go here. The anonymous namespace keeps them private to this file: two task
// files that each define a helper of the same name (say `lerp`) would otherwise not link together.
} // namespace

Vec2 direction_to_uv(Vec3 dir) {
	// TODO (Task 7, handout §7.1): direction -> (theta, phi) -> uv, with the convention in
	// env_light.h.
	// - theta is the angle from +y; phi = atan2(z, x) is in [-pi, pi]: move it into [0, 2 pi).
	// - u must stay below 1 (a tiny negative phi plus 2 pi can round to 2 pi).
	// - Never NaN, also at the poles (x = z = 0).
	(void)dir;
	return Vec2{};
}

Vec3 uv_to_direction(Vec2 uv) {
	// TODO (Task 7, handout §7.1): the inverse of direction_to_uv: theta = pi v, phi = 2 pi u.
	(void)uv;
	return Vec3{0.0f, 1.0f, 0.0f};
}

namespace Samplers::Sphere {

Vec3 Uniform::sample(Vec2 u) const {
	// TODO (Task 7, handout §7.2): a uniformly distributed direction on the unit sphere. Hint: the
	// height y of a uniform point on the sphere is itself uniform in [-1, 1].
	(void)u;
	return Vec3{0.0f, 1.0f, 0.0f};
}

float Uniform::pdf(Vec3 dir) const {
	// TODO (Task 7, handout §7.2): the density of Uniform::sample (the sphere's area is 4 pi).
	(void)dir;
	return 0.0f;
}

Image::Image(const HDR_Image& image) {
	// TODO (Task 7, handout §7.4): set w and h, and fill pdf_texel and cdf (index j * w + i).
	// - A texel's weight is the flux through it: luminance (vec_math.h) times sin(theta) of its row.
	// - The pdf must be non-zero wherever evaluate() is: take the luminance from the texel's 3 x 3
	//   neighbourhood, as the bilinear lookup does (the handout gives two ways).
	// - Normalize by the total (sum in double), so cdf.back() is 1. A black image has total 0.
	(void)image;
}

Vec3 Image::sample(Vec2 u) const {
	// TODO (Task 7, handout §7.4): choose a texel with the cdf (binary search: std::upper_bound),
	// then a uniformly random point inside it in uv, and return its direction.
	(void)u;
	return Vec3{0.0f, 1.0f, 0.0f};
}

float Image::pdf(Vec3 dir) const {
	// TODO (Task 7, handout §7.4): the solid-angle density: the texel's probability over its uv
	// area (pdf_texel * w * h), divided by the Jacobian d omega / (du dv) = 2 pi^2 sin(theta).
	// Return 0 where sin(theta) = 0 instead of dividing by zero.
	(void)dir;
	return 0.0f;
}

} // namespace Samplers::Sphere

Vec3 Env_Map::sample(Vec2 u) const {
	// TODO (Task 7, handouts §7.2 and §7.4): importance-sample with `sampler` when
	// importance_sampling is on, otherwise sample uniformly.
	(void)u;
	return Vec3{0.0f, 1.0f, 0.0f};
}

float Env_Map::pdf(Vec3 dir) const {
	// TODO (Task 7, handouts §7.2 and §7.4): the density matching sample().
	(void)dir;
	return 0.0f;
}

Spectrum Env_Map::evaluate(Vec3 dir) const {
	// TODO (Task 7, handout §7.3): the radiance from `dir`: bilinear interpolation of the four
	// nearest texel centres (in x = u w - 0.5, y = v h - 0.5 the centres sit at integers), wrapping
	// the column index around the seam and clamping the row index at the poles.
	return Spectrum{noise(dir)};
}

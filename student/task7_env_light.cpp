// Task 7: environment light. Handout: handouts/task7_env_light.md
#include "env_light.h"

Vec2 direction_to_uv(Vec3 dir) {
	// TODO (Task 7, handout §7.1): direction -> (theta, phi) -> uv, with the convention in
	// env_light.h.
	(void)dir;
	return Vec2{};
}

Vec3 uv_to_direction(Vec2 uv) {
	// TODO (Task 7, handout §7.1): the inverse of direction_to_uv.
	(void)uv;
	return Vec3{0.0f, 1.0f, 0.0f};
}

namespace Samplers::Sphere {

Vec3 Uniform::sample(Vec2 u) const {
	// TODO (Task 7, handout §7.2): a uniformly distributed direction on the unit sphere.
	(void)u;
	return Vec3{0.0f, 1.0f, 0.0f};
}

float Uniform::pdf(Vec3 dir) const {
	// TODO (Task 7, handout §7.2): the density of Uniform::sample (the sphere's area is 4 pi).
	(void)dir;
	return 0.0f;
}

Image::Image(const HDR_Image& image) {
	// TODO (Task 7, handout §7.4): fill pdf_texel and cdf from luminance * sin(theta) of each
	// texel. Make the pdf non-zero wherever the bilinear radiance is (see the handout).
	(void)image;
}

Vec3 Image::sample(Vec2 u) const {
	// TODO (Task 7, handout §7.4): choose a texel with the cdf, a point inside it, and return its
	// direction.
	(void)u;
	return Vec3{0.0f, 1.0f, 0.0f};
}

float Image::pdf(Vec3 dir) const {
	// TODO (Task 7, handout §7.4): the solid-angle density: texel probability over its uv area,
	// times the Jacobian from uv to directions.
	(void)dir;
	return 0.0f;
}

} // namespace Samplers::Sphere

Vec3 Env_Map::sample(Vec2 u) const {
	// TODO (Task 7, handout §7.3): importance-sample with `sampler` when importance_sampling is
	// on, otherwise sample uniformly.
	(void)u;
	return Vec3{0.0f, 1.0f, 0.0f};
}

float Env_Map::pdf(Vec3 dir) const {
	// TODO (Task 7, handout §7.3): the density matching sample().
	(void)dir;
	return 0.0f;
}

Spectrum Env_Map::evaluate(Vec3 dir) const {
	// TODO (Task 7, handout §7.3): the radiance from `dir`: bilinear interpolation of the four
	// nearest texel centres, wrapping in u and clamping in v.
	(void)dir;
	return Spectrum{0.0f};
}

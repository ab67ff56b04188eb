// Mutant: Image::pdf's Jacobian with |cos theta| (the height y, the sine of the elevation) for sin theta: a density far too small near the poles
// Task 7: environment light. Handout: handouts/task7_env_light.md
#include "env_light.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace {

constexpr float ONE_MINUS_EPSILON = 0x1.fffffep-1f; // the largest float below 1

// Distance of a direction from the y axis: sin(theta) times its length.
float axis_distance(Vec3 dir) {
	return std::sqrt(dir.x * dir.x + dir.z * dir.z);
}

// Texel indices wrap around in u (the seam at phi = 0) and clamp in v (the poles).
uint32_t wrap(int64_t i, uint32_t n) {
	int64_t m = int64_t(n);
	return uint32_t(((i % m) + m) % m);
}
uint32_t clamp_index(int64_t i, uint32_t n) {
	return uint32_t(std::clamp<int64_t>(i, 0, int64_t(n) - 1));
}

// sin(theta) at the centre of row j: the solid angle of a texel is about
// (2 pi / w) (pi / h) sin(theta), so this is the row's share of the sphere.
double row_sin_theta(uint32_t j, uint32_t h) {
	return std::sin((double(j) + 0.5) * M_PI / double(h));
}

// The average over texel (i, j) of the luminance that the bilinear lookup returns (handout §7.4).
// Along each axis the lookup blends a texel with its neighbours; averaged over the texel the
// weights are 1/8 (previous), 3/4 (itself), 1/8 (next). With the lookup's own wrapping and
// clamping this is exact, and it is non-zero wherever the lookup can be: if any texel of the
// 3 x 3 block is bright, part of texel (i, j) is lit.
double texel_average_luminance(const HDR_Image& image, uint32_t i, uint32_t j) {
	constexpr double weight[3] = {0.125, 0.75, 0.125};
	double sum = 0.0;
	for (int dj = -1; dj <= 1; dj++) {
		for (int di = -1; di <= 1; di++) {
			Spectrum L = image.at(wrap(int64_t(i) + di, image.w), clamp_index(int64_t(j) + dj, image.h));
			float Y = luminance(L);
			if (Y > 0.0f) sum += weight[di + 1] * weight[dj + 1] * Y; // negative or NaN pixels emit nothing
		}
	}
	return sum;
}

// Unnormalized probability of each texel (index j * w + i): the flux through it, luminance times
// solid angle. Without `by_luminance`, the solid angle alone (a nearly uniform distribution).
std::vector<double> texel_flux(const HDR_Image& image, bool by_luminance) {
	std::vector<double> flux(size_t(image.w) * image.h);
	for (uint32_t j = 0; j < image.h; j++) {
		for (uint32_t i = 0; i < image.w; i++) {
			double L = by_luminance ? texel_average_luminance(image, i, j) : 1.0;
			flux[size_t(j) * image.w + i] = L * row_sin_theta(j, image.h);
		}
	}
	return flux;
}

} // namespace

Vec2 direction_to_uv(Vec3 dir) {
	// atan2(distance from the axis, height) is accurate near the poles (acos is not) and does not
	// need a unit vector.
	float theta = std::atan2(axis_distance(dir), dir.y); // [0, pi]
	float phi = std::atan2(dir.z, dir.x);                // [-pi, pi]
	float u = (phi < 0.0f ? phi + 2.0f * PI_F : phi) / (2.0f * PI_F);
	// A tiny negative phi plus 2 pi rounds to 2 pi: u = 1 is the meridian u = 0.
	if (u >= 1.0f) u = 0.0f;
	return Vec2{u, theta / PI_F};
}

Vec3 uv_to_direction(Vec2 uv) {
	float phi = 2.0f * PI_F * uv.x;
	float theta = PI_F * uv.y;
	float sin_theta = std::sin(theta);
	return Vec3{sin_theta * std::cos(phi), std::cos(theta), sin_theta * std::sin(phi)};
}

namespace Samplers::Sphere {

Vec3 Uniform::sample(Vec2 u) const {
	// Archimedes: the height of a uniformly distributed point on the sphere is uniform in [-1, 1],
	// and its angle around the axis is uniform in [0, 2 pi).
	float y = 1.0f - 2.0f * u.x; // in (-1, 1], so 1 - y^2 >= 0
	float r = std::sqrt(1.0f - y * y);
	float phi = 2.0f * PI_F * u.y;
	return Vec3{r * std::cos(phi), y, r * std::sin(phi)};
}

float Uniform::pdf(Vec3) const {
	return 1.0f / (4.0f * PI_F); // one over the area of the unit sphere
}

Image::Image(const HDR_Image& image) : w(image.w), h(image.h) {
	std::vector<double> flux = texel_flux(image, true);
	std::vector<double> running(flux.size());
	std::partial_sum(flux.begin(), flux.end(), running.begin());
	if (!(running.back() > 0.0)) {
		// A black image: any distribution is correct, choose texels by solid angle.
		flux = texel_flux(image, false);
		std::partial_sum(flux.begin(), flux.end(), running.begin());
	}
	// Sums in double, normalized by the last one: cdf.back() is exactly 1.
	double total = running.back();
	pdf_texel.resize(flux.size());
	cdf.resize(flux.size());
	for (size_t k = 0; k < flux.size(); k++) {
		pdf_texel[k] = float(flux[k] / total);
		cdf[k] = float(running[k] / total);
	}
}

Vec3 Image::sample(Vec2 u) const {
	// Texel k is chosen when cdf[k - 1] <= u.x < cdf[k]: the first cdf entry above u.x. Since
	// cdf.back() is exactly 1 > u.x, k is a texel with a non-zero probability.
	size_t k = size_t(std::upper_bound(cdf.begin(), cdf.end(), u.x) - cdf.begin());
	// Where u.x falls inside that step is again uniform in [0, 1): reuse it across the texel (u)
	// and u.y down the texel (v).
	float below = k > 0 ? cdf[k - 1] : 0.0f;
	float across = std::min((u.x - below) / (cdf[k] - below), ONE_MINUS_EPSILON);
	uint32_t i = uint32_t(k % w), j = uint32_t(k / w);
	return uv_to_direction(Vec2{(float(i) + across) / float(w), (float(j) + u.y) / float(h)});
}

float Image::pdf(Vec3 dir) const {
	float sin_theta = std::abs(dir.y) / glm::length(dir);
	// At the poles the map from uv to directions folds a whole row into one point: density 0 (a set
	// of directions of measure zero, which sample() reaches only by rounding).
	if (!(sin_theta > 0.0f)) return 0.0f;
	Vec2 uv = direction_to_uv(dir);
	uint32_t i = std::min(uint32_t(uv.x * float(w)), w - 1);
	uint32_t j = std::min(uint32_t(uv.y * float(h)), h - 1);
	// Uniform inside the texel: density pdf_texel * w * h over uv. Over solid angle divide by the
	// Jacobian d omega / (du dv) = (2 pi) (pi) sin(theta).
	float pdf_uv = pdf_texel[size_t(j) * w + i] * float(w) * float(h);
	return pdf_uv / (2.0f * PI_F * PI_F * sin_theta);
}

} // namespace Samplers::Sphere

Vec3 Env_Map::sample(Vec2 u) const {
	return importance_sampling ? sampler.sample(u) : Samplers::Sphere::Uniform{}.sample(u);
}

float Env_Map::pdf(Vec3 dir) const {
	return importance_sampling ? sampler.pdf(dir) : Samplers::Sphere::Uniform{}.pdf(dir);
}

Spectrum Env_Map::evaluate(Vec3 dir) const {
	Vec2 uv = direction_to_uv(dir);
	// Continuous texel coordinates in which texel centres sit at integers.
	float x = uv.x * float(image.w) - 0.5f;
	float y = uv.y * float(image.h) - 0.5f;
	float x0 = std::floor(x), y0 = std::floor(y);
	float fx = x - x0, fy = y - y0;
	// The four nearest texel centres: wrap around the seam, clamp at the poles.
	uint32_t i0 = wrap(int64_t(x0), image.w), i1 = wrap(int64_t(x0) + 1, image.w);
	uint32_t j0 = clamp_index(int64_t(y0), image.h), j1 = clamp_index(int64_t(y0) + 1, image.h);
	Spectrum upper = glm::mix(image.at(i0, j0), image.at(i1, j0), fx);
	Spectrum lower = glm::mix(image.at(i0, j1), image.at(i1, j1), fx);
	return glm::mix(upper, lower, fy);
}

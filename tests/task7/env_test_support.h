#pragma once
// Shared pieces of the task-7 grader: the test's OWN implementation of the convention in
// env_light.h (so expected values never come from the code under test), the maps the tests use,
// and the significance levels.
#include "env_light.h"
#include "rng.h"
#include "statistics.h"

#include <cmath>
#include <sstream>
#include <string>

namespace env_test {

// Significance of every statistical test of the grader, and how many tests share it (Šidák):
// chi-square tests: the uniform sampler and four importance-sampled maps (test_uniform.cpp,
// test_importance.cpp); z-tests: the constant map's three channels (test_importance.cpp), two
// one-texel maps (test_bright_texel.cpp), and three channels of three groups of pixels in
// test_render.cpp (sky and sphere under Env_Map, sphere under Env_Constant).
constexpr double ALPHA = 0.01;
constexpr size_t CHI2_TESTS = 5;
constexpr size_t Z_TESTS = 3 + 2 + 9;

inline double chi2_alpha() {
	return stats::sidak(ALPHA, CHI2_TESTS);
}
inline double z_critical() {
	return stats::two_sided_z(stats::sidak(ALPHA, Z_TESTS));
}

// ---- The convention of env_light.h, in double precision ----------------------------------------

inline Vec3 direction_at(double theta, double phi) {
	return Vec3(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)), float(std::sin(theta) * std::sin(phi)));
}
inline Vec3 direction_at_uv(double u, double v) {
	return direction_at(M_PI * v, 2.0 * M_PI * u);
}
// The direction through image point (x, y) in texel units: texel (i, j) spans [i, i + 1) x [j, j + 1).
inline Vec3 direction_at_texel_point(const HDR_Image& image, double x, double y) {
	return direction_at_uv(x / image.w, y / image.h);
}
// (u, v) of a direction, u in [0, 1), v in [0, 1].
inline Vec2 uv_of(Vec3 d) {
	double theta = std::atan2(std::sqrt(double(d.x) * d.x + double(d.z) * d.z), double(d.y));
	double phi = std::atan2(double(d.z), double(d.x));
	if (phi < 0.0) phi += 2.0 * M_PI;
	double u = phi / (2.0 * M_PI);
	return Vec2(float(u >= 1.0 ? 0.0 : u), float(theta / M_PI));
}

// ---- Messages ------------------------------------------------------------------------------------

inline std::string str(Vec3 v) {
	std::ostringstream s;
	s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
	return s.str();
}
inline std::string str(Vec2 v) {
	std::ostringstream s;
	s << "(" << v.x << ", " << v.y << ")";
	return s.str();
}

// ---- Maps ------------------------------------------------------------------------------------------

// Black except texel (i, j).
inline HDR_Image one_texel_map(uint32_t w, uint32_t h, uint32_t i, uint32_t j, Spectrum value = Spectrum{1.0f}) {
	HDR_Image image(w, h);
	image.at(i, j) = value;
	return image;
}

// A smooth, coloured, everywhere-positive map.
inline HDR_Image gradient_map(uint32_t w = 32, uint32_t h = 16) {
	HDR_Image image(w, h);
	for (uint32_t j = 0; j < h; j++) {
		for (uint32_t i = 0; i < w; i++) {
			float u = (i + 0.5f) / w, v = (j + 0.5f) / h;
			image.at(i, j) = Spectrum{0.2f + 2.0f * u * (1.0f - v), 0.5f + std::sin(PI_F * u), 0.1f + v * v};
		}
	}
	return image;
}

// An outdoor scene in miniature: a sky brightening towards the horizon, a dark ground, and a small
// sun 500 times brighter than the sky (like the HDR maps shipped with the lab, at low resolution).
inline HDR_Image sky_map(uint32_t w = 64, uint32_t h = 32) {
	HDR_Image image(w, h);
	for (uint32_t j = 0; j < h; j++) {
		for (uint32_t i = 0; i < w; i++) {
			float v = (j + 0.5f) / h;
			image.at(i, j) = v < 0.5f ? Spectrum{0.3f, 0.5f, 1.0f} * (0.5f + v) : Spectrum{0.05f, 0.04f, 0.03f};
		}
	}
	for (uint32_t j = 9; j <= 10; j++) {
		for (uint32_t i = 40; i <= 41; i++) image.at(i, j) = Spectrum{500.0f, 480.0f, 450.0f};
	}
	return image;
}

} // namespace env_test

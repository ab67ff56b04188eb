#pragma once
// Shared pieces of the task-7 grader: the requests that hand the student's environment code the
// judge's inputs (grading/judge/protocol.h), and the maps the tests use.
// Expected values never come from the code under test: they are closed forms, or the reference's
// (the judge links the reference of every task, so uv_to_direction and direction_to_uv called here
// are the reference's).
#include "env_light.h"
#include "film_statistics.h"
#include "judge.h"
#include "rng.h"
#include "sample_moments.h"
#include "statistics.h"

#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace env_test {

// z-tests take their standard error from the reference's estimator (reference_weights below, the
// judge's render in test_render.cpp), never from the student's samples; every statistical check is
// made at the grader's level for one check (judge.h: significance).

// ---- Inputs ----------------------------------------------------------------------------------------

// The direction through image point (x, y) of a w x h map, in texel units: texel (i, j) spans
// [i, i + 1) x [j, j + 1) (the reference's uv_to_direction).
inline Vec3 direction_at_texel_point(uint32_t w, uint32_t h, double x, double y) {
	return uv_to_direction(Vec2(float(x / w), float(y / h)));
}

// n points rng.unit2() of a generator seeded with `seed`, in order.
inline std::vector<Vec2> unit_points(uint64_t seed, size_t n) {
	RNG rng(seed);
	std::vector<Vec2> us(n);
	for (Vec2& u : us) u = rng.unit2();
	return us;
}

// ---- Requests --------------------------------------------------------------------------------------

inline protocol::Sampler_Answer student_uniform(const std::vector<Vec2>& us, const std::vector<Vec3>& dirs) {
	return judge::ask(protocol::Uniform_Sphere{us, dirs});
}

inline protocol::Image_Sampler::Answer student_image_sampler(const HDR_Image& image, const std::vector<Vec2>& us,
                                                             const std::vector<Vec3>& dirs) {
	return judge::ask(protocol::Image_Sampler{image, us, dirs});
}

inline protocol::Env_Map_Queries::Answer student_env_map(const HDR_Image& image, bool importance_sampling,
                                                         const std::vector<Vec2>& us, const std::vector<Vec3>& dirs) {
	return judge::ask(protocol::Env_Map_Queries{image, importance_sampling, us, dirs});
}

// The student's Env_Map(image, importance_sampling): sample(u) for each u, then pdf and evaluate
// at those samples (two requests: the second needs the first's answer).
struct Env_Samples {
	std::vector<Vec3> directions;
	std::vector<float> pdfs;
	std::vector<Spectrum> radiance;
};
inline Env_Samples student_env_samples(const HDR_Image& image, bool importance_sampling, const std::vector<Vec2>& us) {
	Env_Samples result;
	result.directions = student_env_map(image, importance_sampling, us, {}).queries.samples;
	protocol::Env_Map_Queries::Answer at = student_env_map(image, importance_sampling, {}, result.directions);
	result.pdfs = at.queries.pdfs;
	result.radiance = at.radiance;
	return result;
}

// ---- The reference's estimates ---------------------------------------------------------------------

// The weights L / pdf per channel of n importance samples of the reference's Env_Map(image) (the
// judge links the reference of every task), from the points of `seed` but another stream than the
// student's; a sample of pdf 0 weighs 0, as a renderer skips it. As many samples as the student's
// are enough: the reference's variance is then off by sqrt((κ - 1) / n) relative, κ the weights'
// kurtosis (measured over 2e5 samples: 36 for the constant map, 27 and 14 for the bright texels),
// 1.3 % at most for n = 2e5, so the standard error by under 0.7 %.
inline std::array<std::vector<double>, 3> reference_weights(const HDR_Image& image, uint64_t seed, size_t n) {
	Env_Map map(image, true);
	std::array<std::vector<double>, 3> weights;
	for (Vec2 u : unit_points(seed ^ 0xa5a5a5a5a5a5a5a5ull, n)) {
		Vec3 d = map.sample(u);
		float pdf = map.pdf(d);
		Spectrum w = pdf > 0.0f ? map.evaluate(d) / pdf : Spectrum{0.0f};
		for (int c = 0; c < 3; c++) weights[c].push_back(double(w[c]));
	}
	return weights;
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

// The bright texel of the 32 x 16 one-texel maps away from the seam and the poles: (11, 6), or with
// a grading seed any texel at least one texel from them.
struct Texel {
	uint32_t i, j;
};
inline Texel inner_bright_texel() {
	std::optional<RNG> secret = judge::secret_inputs();
	if (!secret) return Texel{11, 6};
	RNG& rng = *secret;
	return Texel{1 + rng.integer(30), 1 + rng.integer(14)};
}
inline std::string texel_name(Texel t) {
	return "texel (" + std::to_string(t.i) + ", " + std::to_string(t.j) + ")";
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

// An outdoor scene in miniature, 64 x 32: a sky brightening towards the horizon, a dark ground, and
// a small sun (2 x 2 texels) 500 times brighter than the sky (like the HDR maps shipped with the
// lab, at low resolution). The sun's top-left texel is (40, 9), or with a grading seed anywhere in
// the sky.
inline HDR_Image sky_map() {
	const uint32_t w = 64, h = 32;
	Texel sun{40, 9};
	if (std::optional<RNG> secret = judge::secret_inputs()) {
		RNG& rng = *secret;
		sun = Texel{rng.integer(w - 1), rng.integer(h / 2 - 1)};
	}
	HDR_Image image(w, h);
	for (uint32_t j = 0; j < h; j++) {
		for (uint32_t i = 0; i < w; i++) {
			float v = (j + 0.5f) / h;
			image.at(i, j) = v < 0.5f ? Spectrum{0.3f, 0.5f, 1.0f} * (0.5f + v) : Spectrum{0.05f, 0.04f, 0.03f};
		}
	}
	for (uint32_t j = sun.j; j <= sun.j + 1; j++) {
		for (uint32_t i = sun.i; i <= sun.i + 1; i++) image.at(i, j) = Spectrum{500.0f, 480.0f, 450.0f};
	}
	return image;
}

} // namespace env_test

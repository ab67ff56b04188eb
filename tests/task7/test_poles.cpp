// Task 7 grader, handouts §7.1-§7.4: the poles, where sin(theta) = 0 and phi is undefined, must
// never produce NaN or infinity.
#include "env_test_support.h"

#include <catch2/catch.hpp>

using namespace env_test;

namespace {
// Exactly at the poles, at the two signs of zero, and at tiny distances from the axis (sin(theta)
// from 1e-7 down to 1e-30 and to values whose square underflows).
const Vec3 NEAR_POLES[] = {
	{0.0f, 1.0f, 0.0f},   {0.0f, -1.0f, 0.0f},  {-0.0f, 1.0f, -0.0f}, {-0.0f, -1.0f, 0.0f},
	{1e-7f, 1.0f, 0.0f},  {0.0f, -1.0f, 1e-7f}, {1e-20f, 1.0f, 0.0f}, {-1e-20f, -1.0f, 1e-20f},
	{0.0f, 1.0f, 1e-30f}, {1e-30f, -1.0f, 0.0f}, {3e-39f, 1.0f, 0.0f},
};

struct Named_Env {
	const char* name;
	Env_Map env;
};
} // namespace

TEST_CASE("no NaN or infinity at the poles: direction_to_uv, evaluate and pdf", "[task7][poles]") {
	const Named_Env envs[] = {{"a gradient, importance-sampled", Env_Map(gradient_map(), true)},
	                          {"one bright texel at the north pole, importance-sampled", Env_Map(one_texel_map(32, 16, 5, 0), true)},
	                          {"one bright texel at the south pole, importance-sampled", Env_Map(one_texel_map(32, 16, 5, 15), true)},
	                          {"a gradient, uniformly sampled", Env_Map(gradient_map(), false)}};
	for (Vec3 d : NEAR_POLES) {
		Vec2 uv = direction_to_uv(d);
		INFO("direction_to_uv" << str(d) << " = " << str(uv)
		                       << ": must be finite, v in [0, 1] (use atan2 or clamp the argument of acos, handout §7.1)");
		CHECK(std::isfinite(uv.x));
		CHECK(std::isfinite(uv.y));
		CHECK(uv.y >= 0.0f);
		CHECK(uv.y <= 1.0f);
		for (const Named_Env& e : envs) {
			Spectrum L = e.env.evaluate(d);
			float pdf = e.env.pdf(d);
			INFO(e.name << ": direction " << str(d) << ", evaluate = " << str(L) << ", pdf = " << pdf
			            << ". At the poles sin(theta) = 0: evaluate clamps the row (handout §7.3), pdf returns 0 "
			               "instead of dividing by 0 (handout §7.4)");
			CHECK(is_finite(L));
			CHECK(std::isfinite(pdf));
			CHECK(pdf >= 0.0f);
		}
	}
}

TEST_CASE("no NaN at the poles: sample at the ends of [0, 1)", "[task7][poles]") {
	// u = 0 and the largest float below 1 put samples on the first and last rows' outer edges.
	const Named_Env envs[] = {{"a gradient, importance-sampled", Env_Map(gradient_map(), true)},
	                          {"one bright texel at the north pole", Env_Map(one_texel_map(32, 16, 0, 0), true)},
	                          {"one bright texel at the south pole", Env_Map(one_texel_map(32, 16, 31, 15), true)},
	                          {"a gradient, uniformly sampled", Env_Map(gradient_map(), false)}};
	const float ends[] = {0.0f, 1e-7f, 0.5f, 1.0f - 1e-7f, 0x1.fffffep-1f};
	for (const Named_Env& e : envs) {
		for (float a : ends) {
			for (float b : ends) {
				Vec3 d = e.env.sample(Vec2{a, b});
				float pdf = e.env.pdf(d);
				INFO(e.name << ": sample(" << a << ", " << b << ") = " << str(d) << " with pdf " << pdf
				            << "; must be a finite unit direction with a finite pdf (handouts §7.2, §7.4)");
				CHECK(is_finite(d));
				CHECK(glm::length(d) == Approx(1.0f).epsilon(1e-4));
				CHECK(std::isfinite(pdf));
			}
		}
	}
}

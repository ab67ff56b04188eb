// Task 7 grader, handouts §7.1-§7.4: the poles, where sin(theta) = 0 and phi is undefined, must
// never produce NaN or infinity.
#include "env_test_support.h"

#include "lab_catch2.h"

using namespace env_test;

namespace {
// Exactly at the poles, at the two signs of zero, and at tiny distances from the axis (sin(theta)
// from 1e-7 down to 1e-30 and to values whose square underflows).
const std::vector<Vec3> NEAR_POLES{
	{0.0f, 1.0f, 0.0f},   {0.0f, -1.0f, 0.0f},  {-0.0f, 1.0f, -0.0f}, {-0.0f, -1.0f, 0.0f},
	{1e-7f, 1.0f, 0.0f},  {0.0f, -1.0f, 1e-7f}, {1e-20f, 1.0f, 0.0f}, {-1e-20f, -1.0f, 1e-20f},
	{0.0f, 1.0f, 1e-30f}, {1e-30f, -1.0f, 0.0f}, {3e-39f, 1.0f, 0.0f},
};

struct Named_Env {
	const char* name;
	HDR_Image image;
	bool importance_sampling;
};
} // namespace

TEST_CASE("no NaN or infinity at the poles: direction_to_uv, evaluate and pdf", "[id:t7.poles.no-nan][task7][poles][fn:direction_to_uv][fn:Env_Map::evaluate][fn:Image::pdf]") {
	const Named_Env envs[] = {{"a gradient, importance-sampled", gradient_map(), true},
	                          {"one bright texel at the north pole, importance-sampled", one_texel_map(32, 16, 5, 0), true},
	                          {"one bright texel at the south pole, importance-sampled", one_texel_map(32, 16, 5, 15), true},
	                          {"a gradient, uniformly sampled", gradient_map(), false}};
	std::vector<Vec2> uvs = judge::ask(protocol::Direction_To_UV{NEAR_POLES});
	std::vector<protocol::Env_Map_Queries::Answer> answers;
	for (const Named_Env& e : envs) answers.push_back(student_env_map(e.image, e.importance_sampling, {}, NEAR_POLES));
	for (size_t n = 0; n < NEAR_POLES.size(); n++) {
		Vec3 d = NEAR_POLES[n];
		Vec2 uv = uvs[n];
		INFO("direction_to_uv" << str(d) << " = " << str(uv)
		                       << ": must be finite, v in [0, 1] (use atan2 or clamp the argument of acos, handout §7.1)");
		CHECK(std::isfinite(uv.x));
		CHECK(std::isfinite(uv.y));
		CHECK(uv.y >= 0.0f);
		CHECK(uv.y <= 1.0f);
		for (size_t m = 0; m < std::size(envs); m++) {
			Spectrum L = answers[m].radiance[n];
			float pdf = answers[m].queries.pdfs[n];
			INFO(envs[m].name << ": direction " << str(d) << ", evaluate = " << str(L) << ", pdf = " << pdf
			                  << ". At the poles sin(theta) = 0: evaluate clamps the row (handout §7.3), pdf returns 0 "
			                     "instead of dividing by 0 (handout §7.4)");
			CHECK(is_finite(L));
			CHECK(std::isfinite(pdf));
			CHECK(pdf >= 0.0f);
		}
	}
}

TEST_CASE("no NaN at the poles: sample at the ends of [0, 1)", "[id:t7.poles.sample-ends][task7][poles][fn:Image::sample]") {
	// u = 0 and the largest float below 1 put samples on the first and last rows' outer edges.
	const Named_Env envs[] = {{"a gradient, importance-sampled", gradient_map(), true},
	                          {"one bright texel at the north pole", one_texel_map(32, 16, 0, 0), true},
	                          {"one bright texel at the south pole", one_texel_map(32, 16, 31, 15), true},
	                          {"a gradient, uniformly sampled", gradient_map(), false}};
	const float ends[] = {0.0f, 1e-7f, 0.5f, 1.0f - 1e-7f, 0x1.fffffep-1f};
	std::vector<Vec2> us;
	for (float a : ends) {
		for (float b : ends) us.push_back(Vec2{a, b});
	}
	for (const Named_Env& e : envs) {
		Env_Samples samples = student_env_samples(e.image, e.importance_sampling, us);
		for (size_t n = 0; n < us.size(); n++) {
			Vec3 d = samples.directions[n];
			float pdf = samples.pdfs[n];
			INFO(e.name << ": sample(" << us[n].x << ", " << us[n].y << ") = " << str(d) << " with pdf " << pdf
			            << "; must be a finite unit direction with a finite pdf (handouts §7.2, §7.4)");
			CHECK(is_finite(d));
			CHECK(glm::length(d) == Approx(1.0f).epsilon(1e-4));
			CHECK(std::isfinite(pdf));
		}
	}
}

// Task 7 grader, handout §7.2: uniform sampling of the sphere, and which sampler each environment
// uses.
#include "env_test_support.h"
#include "sphere_chi2.h"

#include <catch2/catch.hpp>

using namespace env_test;

namespace {
constexpr float UNIFORM_PDF = float(1.0 / (4.0 * M_PI));

const Vec3 SOME_DIRECTIONS[] = {{0, 1, 0}, {0, -1, 0}, {1, 0, 0}, {0, 0, -1}, {0.6f, 0.0f, 0.8f}, {0.48f, 0.6f, -0.64f}};
} // namespace

TEST_CASE("Uniform::pdf is 1 / (4 pi) in every direction", "[task7][uniform]") {
	Samplers::Sphere::Uniform uniform;
	for (Vec3 d : SOME_DIRECTIONS) {
		INFO("Uniform::pdf" << str(d) << " = " << uniform.pdf(d)
		                    << ", expected 1 / (4 pi) = " << UNIFORM_PDF << ": the sphere's area is 4 pi (handout §7.2)");
		CHECK(uniform.pdf(d) == Approx(UNIFORM_PDF).epsilon(1e-6));
	}
}

TEST_CASE("Uniform::sample returns unit directions, even for u at the ends of [0, 1)", "[task7][uniform]") {
	Samplers::Sphere::Uniform uniform;
	const float ends[] = {0.0f, 0.5f, 0x1.fffffep-1f};
	for (float a : ends) {
		for (float b : ends) {
			Vec3 d = uniform.sample(Vec2{a, b});
			INFO("Uniform::sample(" << a << ", " << b << ") = " << str(d)
			                        << ": must be a finite unit vector (handout §7.2)");
			CHECK(is_finite(d));
			CHECK(glm::length(d) == Approx(1.0f).epsilon(1e-5));
		}
	}
}

TEST_CASE("Uniform::sample covers the sphere uniformly (chi-square)", "[task7][uniform][statistical]") {
	Samplers::Sphere::Uniform uniform;
	stats::Sphere_Chi2_Settings settings;
	settings.seed = 73;
	auto result = stats::sphere_chi2([&](RNG& rng) { return uniform.sample(rng.unit2()); },
	                                 [&](Vec3 d) { return uniform.pdf(d); }, settings);
	INFO("Uniform::sample must be distributed with the density Uniform::pdf (handout §7.2: y = 1 - 2 u uniform in "
	     "[-1, 1], phi = 2 pi u uniform): "
	     << result.summary() << "; significance " << chi2_alpha());
	CHECK(result.pass(chi2_alpha()));
}

TEST_CASE("Env_Constant samples uniformly: its pdf is 1 / (4 pi)", "[task7][uniform]") {
	// Env_Constant (framework) delegates to Samplers::Sphere::Uniform.
	Env_Constant env;
	for (Vec3 d : SOME_DIRECTIONS) {
		INFO("Env_Constant::pdf" << str(d) << " = " << env.pdf(d) << ", expected 1 / (4 pi): Uniform::pdf (handout §7.2)");
		CHECK(env.pdf(d) == Approx(UNIFORM_PDF).epsilon(1e-6));
	}
}

TEST_CASE("Env_Map without importance sampling samples the sphere uniformly", "[task7][uniform]") {
	Env_Map env(gradient_map(), false);
	for (Vec3 d : SOME_DIRECTIONS) {
		INFO("Env_Map::pdf" << str(d) << " = " << env.pdf(d)
		                    << " with importance_sampling off; expected the uniform 1 / (4 pi) (handout §7.2)");
		CHECK(env.pdf(d) == Approx(UNIFORM_PDF).epsilon(1e-6));
	}
	RNG rng(74);
	Samplers::Sphere::Uniform uniform;
	for (int n = 0; n < 100; n++) {
		Vec2 u = rng.unit2();
		INFO("Env_Map::sample" << str(u) << " = " << str(env.sample(u)) << " with importance_sampling off; expected "
		                       << "Samplers::Sphere::Uniform's sample " << str(uniform.sample(u)) << " (handout §7.2)");
		REQUIRE(env.sample(u) == uniform.sample(u));
	}
}

TEST_CASE("Env_Map with importance sampling uses its Image sampler", "[task7][uniform]") {
	Env_Map env(gradient_map(), true);
	RNG rng(75);
	for (int n = 0; n < 100; n++) {
		Vec2 u = rng.unit2();
		Vec3 d = env.sampler.sample(u);
		INFO("with importance_sampling on, Env_Map::sample and pdf must be those of `sampler` (handout §7.4): "
		     << "sample" << str(u) << " = " << str(env.sample(u)) << " vs sampler.sample = " << str(d) << "; pdf "
		     << env.pdf(d) << " vs sampler.pdf = " << env.sampler.pdf(d));
		REQUIRE(env.sample(u) == d);
		REQUIRE(env.pdf(d) == env.sampler.pdf(d));
	}
}

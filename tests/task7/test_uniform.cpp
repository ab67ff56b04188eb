// Task 7 grader, handout §7.2: uniform sampling of the sphere, and which sampler each environment
// uses.
#include "env_test_support.h"
#include "sphere_chi2.h"

#include "lab_catch2.h"

using namespace env_test;

namespace {
constexpr float UNIFORM_PDF = float(1.0 / (4.0 * M_PI));

// The poles, the axes and two directions between them; with a grading seed, six directions drawn
// uniformly (the reference's uniform sampler).
std::vector<Vec3> some_directions() {
	std::optional<RNG> secret = judge::secret_inputs();
	if (!secret) {
		return {{0, 1, 0}, {0, -1, 0}, {1, 0, 0}, {0, 0, -1}, {0.6f, 0.0f, 0.8f}, {0.48f, 0.6f, -0.64f}};
	}
	std::vector<Vec3> dirs;
	for (int n = 0; n < 6; n++) dirs.push_back(Samplers::Sphere::Uniform{}.sample(secret->unit2()));
	return dirs;
}
} // namespace

TEST_CASE("Uniform::pdf is 1 / (4 pi) in every direction", "[id:t7.uniform.pdf][task7][uniform][fn:Uniform::pdf]") {
	std::vector<Vec3> dirs = some_directions();
	std::vector<float> pdfs = student_uniform({}, dirs).pdfs;
	for (size_t n = 0; n < dirs.size(); n++) {
		INFO("Uniform::pdf" << str(dirs[n]) << " = " << pdfs[n] << ", expected 1 / (4 pi) = " << UNIFORM_PDF
		                    << ": the sphere's area is 4 pi (handout §7.2)");
		CHECK(pdfs[n] == Approx(UNIFORM_PDF).epsilon(1e-6));
	}
}

TEST_CASE("Uniform::sample returns unit directions, even for u at the ends of [0, 1)", "[id:t7.uniform.unit-directions][task7][uniform][fn:Uniform::sample]") {
	const float ends[] = {0.0f, 0.5f, 0x1.fffffep-1f};
	std::vector<Vec2> us;
	for (float a : ends) {
		for (float b : ends) us.push_back(Vec2{a, b});
	}
	std::vector<Vec3> samples = student_uniform(us, {}).samples;
	for (size_t n = 0; n < us.size(); n++) {
		Vec3 d = samples[n];
		INFO("Uniform::sample(" << us[n].x << ", " << us[n].y << ") = " << str(d)
		                        << ": must be a finite unit vector (handout §7.2)");
		CHECK(is_finite(d));
		CHECK(glm::length(d) == Approx(1.0f).epsilon(1e-5));
	}
}

TEST_CASE("Uniform::sample covers the sphere uniformly (chi-square)", "[id:t7.uniform.chi2][statistical:1][task7][uniform][fn:Uniform::sample]") {
	stats::Sphere_Chi2_Settings settings;
	settings.seed = judge::secret_seed_or(73);
	protocol::Sampler_Answer answer =
		student_uniform(unit_points(settings.seed, settings.samples), stats::sphere_chi2_pdf_directions(settings));
	auto result = stats::sphere_chi2(answer.samples, answer.pdfs, settings);
	const double alpha = judge::significance();
	INFO("Uniform::sample must be distributed with the density Uniform::pdf (handout §7.2: y = 1 - 2 u uniform in "
	     "[-1, 1], phi = 2 pi u uniform): "
	     << result.summary() << "; significance " << alpha);
	CHECK(result.pass(alpha));
}

TEST_CASE("Env_Constant samples uniformly: its pdf is 1 / (4 pi)", "[id:t7.env-constant.uniform][task7][uniform][uses:Uniform::sample][uses:Uniform::pdf]") {
	// Env_Constant (framework) delegates to Samplers::Sphere::Uniform.
	std::vector<Vec3> dirs = some_directions();
	std::vector<float> pdfs = judge::ask(protocol::Env_Constant_Queries{Spectrum{1.0f}, {}, dirs}).queries.pdfs;
	for (size_t n = 0; n < dirs.size(); n++) {
		INFO("Env_Constant::pdf" << str(dirs[n]) << " = " << pdfs[n] << ", expected 1 / (4 pi): Uniform::pdf (handout §7.2)");
		CHECK(pdfs[n] == Approx(UNIFORM_PDF).epsilon(1e-6));
	}
}

TEST_CASE("Env_Map without importance sampling samples the sphere uniformly", "[id:t7.env-map.uniform][task7][uniform][fn:Env_Map::sample][uses:Uniform::sample][uses:Uniform::pdf]") {
	std::vector<Vec3> dirs = some_directions();
	std::vector<Vec2> us = unit_points(judge::secret_seed_or(74), 100);
	protocol::Env_Map_Queries::Answer env = student_env_map(gradient_map(), false, us, dirs);
	for (size_t n = 0; n < dirs.size(); n++) {
		INFO("Env_Map::pdf" << str(dirs[n]) << " = " << env.queries.pdfs[n]
		                    << " with importance_sampling off; expected the uniform 1 / (4 pi) (handout §7.2)");
		CHECK(env.queries.pdfs[n] == Approx(UNIFORM_PDF).epsilon(1e-6));
	}
	std::vector<Vec3> uniform = student_uniform(us, {}).samples;
	for (size_t n = 0; n < us.size(); n++) {
		INFO("Env_Map::sample" << str(us[n]) << " = " << str(env.queries.samples[n])
		                       << " with importance_sampling off; expected Samplers::Sphere::Uniform's sample "
		                       << str(uniform[n]) << " (handout §7.2)");
		REQUIRE(env.queries.samples[n] == uniform[n]);
	}
}

TEST_CASE("Env_Map with importance sampling uses its Image sampler", "[id:t7.env-map.importance][task7][uniform][fn:Env_Map::sample][fn:Env_Map::pdf][uses:Image::sample][uses:Image::pdf]") {
	// The pdfs are compared at directions spread like importance samples (the reference's).
	HDR_Image image = gradient_map();
	std::vector<Vec2> us = unit_points(judge::secret_seed_or(75), 100);
	std::vector<Vec3> dirs;
	Samplers::Sphere::Image reference(image);
	for (Vec2 u : us) dirs.push_back(reference.sample(u));
	protocol::Env_Map_Queries::Answer env = student_env_map(image, true, us, dirs);
	protocol::Sampler_Answer sampler = student_image_sampler(image, us, dirs).queries;
	for (size_t n = 0; n < us.size(); n++) {
		INFO("with importance_sampling on, Env_Map::sample and pdf must be those of `sampler` (handout §7.4): "
		     << "sample" << str(us[n]) << " = " << str(env.queries.samples[n]) << " vs sampler.sample = "
		     << str(sampler.samples[n]) << "; pdf " << env.queries.pdfs[n] << " vs sampler.pdf = " << sampler.pdfs[n]
		     << " at " << str(dirs[n]));
		REQUIRE(env.queries.samples[n] == sampler.samples[n]);
		REQUIRE(env.queries.pdfs[n] == sampler.pdfs[n]);
	}
}

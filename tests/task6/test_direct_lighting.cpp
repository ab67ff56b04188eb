// Task 6 grader, part 2: what the mixture estimates (handout §6.1, §6.2, §6.4). Closed forms for the
// light a diffuse surface reflects (Lambert's formula for a square light, pi L (r/d)^2 cos(beta) for a
// sphere), the three strategies agreeing on them, the variance the mixture saves under a small
// light, and full renders with max_depth 1.
#include "direct_lighting_estimators.h"
#include "grader_significance.h"
#include "light_closed_forms.h"
#include "light_scenes.h"

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace {

const float RHO = 0.5f; // albedo of every receiver
const BSDF GREY{BSDF_Lambertian{Spectrum{RHO}}};

// n samples of the light reflected at `point` towards out_dir with one strategy.
Sample_Moments estimate(const Pathtracer& pt, Strategy strategy, const Trace& point, Vec3 out_dir, size_t n,
                        uint64_t seed) {
	std::vector<double> samples(n);
	RNG rng(seed);
	for (double& x : samples) x = reflected_radiance_sample(pt, strategy, rng, point, GREY, out_dir);
	return moments(samples);
}

// z-test of an estimate against the closed form.
void check_estimate(const Sample_Moments& m, double expected, const std::string& what) {
	double z = (m.mean - expected) / m.standard_error();
	INFO(what << ": estimated " << m.mean << " +- " << m.standard_error() << " (" << m.n << " samples), closed form "
	          << expected << ", z = " << z << " (critical " << task6::z_critical() << ")");
	CHECK(std::abs(z) <= task6::z_critical());
}

// n camera samples of pixel (0, 0), with the film's per-sample RNG.
Sample_Moments render_samples(const Pathtracer& pt, size_t n) {
	std::vector<double> samples(n);
	for (size_t i = 0; i < n; i++) {
		RNG rng = RNG::for_sample(pt.settings.seed, 0, i);
		Spectrum v = pt.trace_pixel(0, 0, rng);
		samples[i] = (double(v.r) + double(v.g) + double(v.b)) / 3.0;
	}
	return moments(samples);
}

// A large grey floor (y = 0, facing up) under a square light, seen by a 1 x 1 pixel camera whose
// field of view (0.05 degrees) is so narrow that it sees only the floor's centre: there the
// irradiance varies by less than 1e-6 across the pixel.
Scene lit_floor(float half_side, float height, Spectrum radiance, Vec3 eye) {
	Scene scene;
	add_object(scene, parallelogram(Vec3{-3.0f, 0.0f, -3.0f}, Vec3{0.0f, 0.0f, 6.0f}, Vec3{6.0f, 0.0f, 0.0f}),
	           add_material(scene, diffuse_material(Spectrum{RHO}), "floor"));
	add_object(scene, ceiling_square(half_side, height), add_material(scene, emitter(radiance), "light"));
	scene.camera = Camera::look_at(eye, Vec3{0.0f}, Vec3{0.0f, 1.0f, 0.0f}, 0.05f, 1.0f);
	return scene;
}

Render_Settings one_pixel(uint64_t seed) {
	Render_Settings settings;
	settings.width = settings.height = 1;
	settings.max_depth = 1; // direct light only
	settings.seed = seed;
	return settings;
}

} // namespace

TEST_CASE("BSDF sampling, light sampling and the mixture all estimate the light Lambert's formula gives",
          "[task6]") {
	// A tilted, off-centre receiver under a square light (half-side 0.5, height 1, radiance 1):
	// L_o = rho E / pi, E from Lambert's formula for polygons.
	Scene scene = ceiling_light_scene(0.5f, 1.0f);
	Pathtracer pt(scene, Render_Settings{});
	Vec3 position{0.2f, 0.0f, -0.1f}, normal = glm::normalize(Vec3{0.25f, 1.0f, -0.15f});
	Vec3 out_dir = glm::normalize(Vec3{-0.3f, 1.0f, 0.4f});
	double e = closed_form::polygon_irradiance(ceiling_square_corners(0.5f, 1.0f), glm::dvec3(position),
	                                           glm::dvec3(normal), 1.0);
	double expected = RHO * e / M_PI;
	Trace point = surface_point(position, normal);

	check_estimate(estimate(pt, Strategy::bsdf, point, out_dir, 100000, 11), expected,
	               "BSDF sampling alone (the grader's own estimator: a failure here is a framework bug)");
	check_estimate(estimate(pt, Strategy::lights, point, out_dir, 100000, 12), expected,
	               "light sampling alone (the grader's own estimator: a failure here is a framework bug)");
	check_estimate(estimate(pt, Strategy::mixture, point, out_dir, 100000, 13), expected,
	               "sample_incoming's mixture, weighted attenuation * |cos| / pdf: a biased mean means the pdf "
	               "does not match how the direction was drawn (handout §6.2)");
}

TEST_CASE("the mixture estimates the light from a sphere: E = pi L (r/d)^2 cos(beta)", "[task6]") {
	// A sphere light of radius 0.5 at distance 2 along a direction 30 degrees from the normal.
	Scene scene;
	add_object(scene, Sphere{0.5f}, add_material(scene, emitter(Spectrum{1.0f}), "light"),
	           glm::translate(Mat4{1.0f}, Vec3{0.0f, 2.0f, 0.0f}));
	scene.commit();
	Pathtracer pt(scene, Render_Settings{});
	Vec3 normal{std::sin(PI_F / 6.0f), std::cos(PI_F / 6.0f), 0.0f};
	double expected = RHO * closed_form::sphere_irradiance(0.5, 2.0, std::cos(M_PI / 6.0), 1.0) / M_PI;
	check_estimate(estimate(pt, Strategy::mixture, surface_point(Vec3{0.0f}, normal), normal, 100000, 21), expected,
	               "sample_incoming's mixture under a sphere light (handout §6.2)");
}

TEST_CASE("under a small light, the mixture has a lower variance than BSDF sampling alone", "[task6]") {
	// Square of half-side 0.1 at height 1: BSDF sampling finds it 1.3% of the time, light sampling
	// every time. One-sided z-test of var(BSDF) - var(mixture) > 0, with the sampling variance of
	// a sample variance, (m4 - s^4) / n.
	Scene scene = ceiling_light_scene(0.1f, 1.0f);
	Pathtracer pt(scene, Render_Settings{});
	Trace point = surface_point(Vec3{0.0f}, Vec3{0.0f, 1.0f, 0.0f});
	Vec3 out_dir{0.0f, 1.0f, 0.0f};
	Sample_Moments bsdf = estimate(pt, Strategy::bsdf, point, out_dir, 100000, 31);
	Sample_Moments mixture = estimate(pt, Strategy::mixture, point, out_dir, 100000, 32);
	double z = (bsdf.variance - mixture.variance) /
	           std::sqrt(bsdf.variance_of_variance() + mixture.variance_of_variance());
	double critical = stats::normal_quantile(1.0 - task6::check_alpha());
	INFO("per-sample variance: BSDF sampling " << bsdf.variance << ", sample_incoming " << mixture.variance
	                                           << " (z = " << z << ", must exceed " << critical
	                                           << "). Light sampling is what makes small lights cheap "
	                                           << "(handout §6.1)");
	CHECK(z > critical);
}

TEST_CASE("a diffuse floor under a square light renders as rho E / pi (max_depth 1)", "[task6]") {
	// Lambert's formula for a parallel square of half-side a at height h, under its centre:
	// a/h = 0.5 -> E = 0.752275 L, a/h = 1 -> E = 1.740840 L (testing-anchors §4).
	REQUIRE(closed_form::centred_square_irradiance(0.5, 1.0, 1.0) == Approx(0.752275).epsilon(1e-6));
	REQUIRE(closed_form::centred_square_irradiance(1.0, 1.0, 1.0) == Approx(1.740840).epsilon(1e-6));
	struct Case {
		float half_side, height, radiance;
		uint64_t seed;
	};
	for (Case c : {Case{0.5f, 1.0f, 2.0f, 41}, Case{1.0f, 1.0f, 1.0f, 42}}) {
		Scene scene = lit_floor(c.half_side, c.height, Spectrum{c.radiance}, Vec3{0.6f, 0.4f, 0.5f});
		scene.commit();
		Pathtracer pt(scene, one_pixel(c.seed));
		double e = closed_form::centred_square_irradiance(c.half_side, c.height, c.radiance);
		check_estimate(render_samples(pt, 50000), RHO * e / M_PI,
		               "pixel under a square light with a/h = " + std::to_string(c.half_side / c.height) +
		                   ", L = " + std::to_string(c.radiance) + " (the renderer with your sample_incoming, "
		                   "handout §6.2)");
	}
}

TEST_CASE("a light hidden behind a blocker gives exactly 0", "[task6]") {
	// A black square between the floor and the light covers the light as seen from the floor's
	// centre; the camera looks at that centre from the side, under the blocker. No direction can
	// bring light, so every sample is exactly 0, never NaN.
	Scene scene = lit_floor(0.5f, 1.0f, Spectrum{1.0f}, Vec3{2.0f, 0.1f, 0.0f});
	add_object(scene, ceiling_square(0.6f, 0.5f), add_material(scene, diffuse_material(Spectrum{0.0f}), "blocker"));
	scene.commit();
	Pathtracer pt(scene, one_pixel(51));
	for (size_t i = 0; i < 20000; i++) {
		RNG rng = RNG::for_sample(pt.settings.seed, 0, i);
		Spectrum v = pt.trace_pixel(0, 0, rng);
		INFO("sample " << i << " of an occluded light: (" << v.r << ", " << v.g << ", " << v.b
		               << "); light must arrive only along rays that reach it (handout §6.2)");
		REQUIRE(v == Spectrum{0.0f});
	}
}

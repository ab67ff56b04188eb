// Which light a light sample aims at (framework/scene/light_distribution.h): by power, each light in
// proportion to the power it emits (chi-square on the choices), with the same probabilities in
// every density that counts the choice (area_lights_pdf, sample_light, the NEE integrator's weight
// of a light found by a BSDF sample), whichever the choice (the light tree's own tests:
// tests/framework/test_light_tree.cpp). That the choice changes only the noise, not the image, is
// tested on every shipped scene by tests/framework/test_integrators.cpp.
#include "estimator.h"
#include "light_distribution.h"
#include "light_scenes.h"
#include "nee_integrator.h"
#include "pathtracer.h"
#include "statistics.h"

#include "lab_catch2.h"
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace {

// Three lights of very different power around the origin: a bright small square above (light 0),
// a dim large square below (light 1), both facing it, and a constant sky (light 2).
Scene three_lights() {
	Scene scene;
	add_object(scene, ceiling_square(0.2f, 2.0f), add_material(scene, emitter(Spectrum{30.0f, 20.0f, 10.0f}), "bright"));
	add_object(scene, parallelogram(Vec3{-1.0f, -2.0f, -1.0f}, Vec3{0.0f, 0.0f, 2.0f}, Vec3{2.0f, 0.0f, 0.0f}),
	           add_material(scene, emitter(Spectrum{0.5f}), "dim"));
	scene.environment = Env_Constant{Spectrum{0.02f}};
	scene.commit();
	return scene;
}

Pathtracer choosing(const Scene& scene, Light_Choice choice) {
	Estimator_Choice estimator;
	estimator.light_choice = choice;
	return Pathtracer(scene, Render_Settings{}, View::path, estimator);
}

} // namespace

TEST_CASE("light powers: pi * area * luminance for area lights, pi R^2 * integral for the environment",
          "[light_choice]") {
	Scene scene = three_lights();
	std::vector<double> powers = light_powers(scene);
	REQUIRE(powers.size() == 3);
	CHECK(powers[0] == Approx(M_PI * 0.4 * 0.4 * luminance(Spectrum{30.0f, 20.0f, 10.0f})).epsilon(1e-5));
	CHECK(powers[1] == Approx(M_PI * 2.0 * 2.0 * 0.5).epsilon(1e-5));
	// The scene's box runs from (-1, -2, -1) to (1, 2, 1): R^2 = (4 + 16 + 4) / 4.
	CHECK(powers[2] == Approx(M_PI * 6.0 * 4.0 * M_PI * 0.02).epsilon(1e-5));

	// An image environment integrates luminance * sin(theta) over its texels: a constant image is
	// 4 pi L (to the midpoint rule's accuracy with 64 rows).
	scene.environment = Env_Map(HDR_Image(128, 64, Spectrum{0.02f}), false);
	CHECK(light_powers(scene)[2] == Approx(M_PI * 6.0 * 4.0 * M_PI * 0.02).epsilon(1e-3));
}

TEST_CASE("Light_Choice::power chooses each light by its power, half of the probability spread evenly (chi-square)",
          "[light_choice]") {
	Scene scene = three_lights();
	std::vector<double> powers = light_powers(scene);
	double total = powers[0] + powers[1] + powers[2];
	Light_Distribution distribution(scene, Light_Choice::power);
	for (size_t i = 0; i < 3; i++) {
		double expected = 0.5 * powers[i] / total + 0.5 / 3.0; // Light_Distribution::UNIFORM_SHARE
		CHECK(distribution.probability(i, Vec3{0.0f}) == Approx(expected).epsilon(1e-6));
	}

	const size_t n = 1000000;
	std::vector<double> observed(3, 0.0), expected(3);
	RNG rng(17);
	for (size_t k = 0; k < n; k++) observed[distribution.choose(rng, Vec3{0.0f}).light] += 1.0;
	for (size_t i = 0; i < 3; i++) expected[i] = n * double(distribution.probability(i, Vec3{0.0f}));
	stats::Chi2_Result result = stats::chi2_test(observed, expected);
	INFO("choices " << observed[0] << " / " << observed[1] << " / " << observed[2] << ", expected " << expected[0]
	                << " / " << expected[1] << " / " << expected[2]);
	CHECK(result.p_value > 0.01);
}

TEST_CASE("Light_Choice::uniform, and a scene whose lights changed, choose every light equally often",
          "[light_choice]") {
	Scene scene = three_lights();
	Light_Distribution uniform(scene, Light_Choice::uniform);
	for (size_t i = 0; i < 3; i++) CHECK(uniform.probability(i, Vec3{0.0f}) == Approx(1.0 / 3.0));

	Light_Choice choice = GENERATE(Light_Choice::power, Light_Choice::tree);
	Light_Distribution chosen(scene, choice);
	scene.environment.reset(); // a light taken out after the distribution was made
	for (size_t i = 0; i < 2; i++) CHECK(chosen.probability(i, Vec3{0.0f}) == 0.5f);
	RNG rng(3);
	for (int k = 0; k < 1000; k++) REQUIRE(chosen.choose(rng, Vec3{0.0f}).light < 2);
}

TEST_CASE("area_lights_pdf weighs each light's density by its probability", "[light_choice]") {
	Scene scene = three_lights();
	Light_Choice choice = GENERATE(Light_Choice::power, Light_Choice::tree);
	Pathtracer pt = choosing(scene, choice);
	Vec3 from{0.1f, 0.0f, 0.2f};
	RNG rng(5);
	for (int k = 0; k < 1000; k++) {
		Vec3 dir = pt.sample_area_lights(rng, from);
		const Light_Distribution& lights = pt.estimator().lights;
		double expected = lights.probability(0, from) * scene.area_lights.pdf(0, from, dir) +
		                  lights.probability(1, from) * scene.area_lights.pdf(1, from, dir) +
		                  lights.probability(2, from) / (4.0 * M_PI);
		CAPTURE(k, dir.x, dir.y, dir.z);
		REQUIRE(pt.area_lights_pdf(from, dir) == Approx(expected).epsilon(1e-5));
	}
}

TEST_CASE("sample_light's density is the NEE integrator's density of the point it chose", "[light_choice]") {
	// What sample_light draws (a point on a light, or a sky direction) and what the NEE integrator
	// weighs a BSDF sample's emission by must be the same density, or the power heuristic's two
	// weights do not add up to 1. A ray from `from` towards the sampled point finds it; its
	// density there must be the sample's.
	Scene scene = three_lights();
	Light_Choice choice = GENERATE(Light_Choice::uniform, Light_Choice::power, Light_Choice::tree);
	Pathtracer pt = choosing(scene, choice);
	Vec3 from{0.1f, 0.0f, 0.2f};
	RNG rng(9);
	size_t checked = 0;
	for (int k = 0; k < 2000; k++) {
		Light_Sample sample = pt.sample_light(rng, from);
		REQUIRE(sample.pdf > 0.0f);
		Ray ray(from, sample.direction);
		Trace hit = scene.hit(ray);
		bool found = sample.distance == INF_F ? !hit.hit : std::abs(hit.distance - sample.distance) <= 1e-4f * sample.distance;
		if (!found) continue; // hidden behind another light
		CAPTURE(k, sample.distance, hit.hit);
		REQUIRE(light_pdf(pt, ray, hit) == Approx(sample.pdf).epsilon(1e-4));
		checked++;
	}
	CHECK(checked > 1000);
}

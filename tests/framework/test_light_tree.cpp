// The light tree (framework/scene/light_tree.h, Light_Choice::tree): at any shading point its
// probabilities of the scene's lights sum to 1, it chooses each light as often as that probability
// says (chi-square), and the probability it reports with a light is exactly the one it gives that
// light when asked again (what the NEE integrator's MIS weight needs). Its bounds never rule out a
// light that can light the point, and with one light it renders exactly what choice by power
// renders. That images rendered with it are the same as with the other
// choices is tested by tests/framework/test_integrators.cpp; that they do not depend on the
// threads, by tests/framework/test_render.cpp.
#include "light_bounds.h"
#include "estimator.h"
#include "light_distribution.h"
#include "light_scenes.h"
#include "render.h"
#include "scene_loader.h"
#include "statistics.h"

#include "lab_catch2.h"
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstring>

namespace {

// 48 small square lamps on an 8 x 6 grid at heights between 1.5 and 3.5, facing down, tilted or
// (one in seven) up, of emission 1 to 50; two sphere lamps; and a dim sky.
Scene field_of_lamps() {
	Scene scene;
	RNG rng(2024);
	for (int k = 0; k < 48; k++) {
		Vec3 centre{-4.0f + float(k % 8), 1.5f + 2.0f * rng.unit(), -3.0f + float(k / 8)};
		Vec3 u{0.3f, 0.0f, 0.0f}, v{0.0f, 0.0f, 0.3f};
		Mat4 tilt = glm::rotate(Mat4{1.0f}, 1.2f * (rng.unit() - 0.5f), Vec3{1.0f, 0.0f, 0.0f});
		if (k % 7 == 0) std::swap(u, v); // facing up
		Tri_Mesh lamp = parallelogram(Vec3{0.0f} - 0.5f * (u + v), u, v);
		Mat4 to_world = glm::translate(Mat4{1.0f}, centre) * tilt;
		float emission = 1.0f + 49.0f * rng.unit();
		add_object(scene, lamp, add_material(scene, emitter(Spectrum{emission}), "lamp " + std::to_string(k)), to_world);
	}
	for (float x : {-2.0f, 3.0f}) {
		add_object(scene, Sphere{0.2f}, add_material(scene, emitter(Spectrum{5.0f}), "ball"),
		           glm::translate(Mat4{1.0f}, Vec3{x, 1.0f, 0.0f}));
	}
	scene.environment = Env_Constant{Spectrum{0.05f}};
	scene.commit();
	return scene;
}

// Shading points: under the lamps, beside them, among them, above them all, far away.
const std::vector<Vec3> POINTS{{0.1f, 0.0f, 0.2f}, {6.0f, 1.0f, -1.0f}, {-1.3f, 2.4f, 0.6f}, {0.0f, 9.0f, 0.0f},
                               {40.0f, 3.0f, 25.0f}};

// The lights' probabilities at p: the area lights', then the environment's.
std::vector<double> probabilities(const Light_Distribution& tree, const Scene& scene, Vec3 p) {
	std::vector<double> p_light;
	for (size_t i = 0; i < light_count(scene); i++) p_light.push_back(tree.probability(i, p));
	return p_light;
}

} // namespace

TEST_CASE("the light tree's probabilities of all lights sum to 1 at any point", "[light_tree]") {
	Scene scene = field_of_lamps();
	Light_Distribution tree(scene, Light_Choice::tree);
	// Each probability is a product of one factor per level of the tree (depth ceil(log2 50) = 6 for
	// a median split), each factor and product rounded once or twice: relative error at most
	// 2 (depth + 1) 2^-24 (plus one for the environment's share, which is exact).
	const double rounding = 2.0 * (6 + 1) * 0x1p-24;
	for (Vec3 p : POINTS) {
		std::vector<double> p_light = probabilities(tree, scene, p);
		double sum = 0.0;
		for (double q : p_light) {
			REQUIRE(q >= 0.0);
			sum += q;
		}
		CAPTURE(p.x, p.y, p.z);
		CHECK(std::abs(sum - 1.0) <= rounding);
	}
}

TEST_CASE("the light tree leaves the sky between a quarter and three quarters of the samples, more far from the lamps",
          "[light_tree]") {
	Scene scene = field_of_lamps();
	Light_Distribution tree(scene, Light_Choice::tree);
	size_t sky = scene.area_lights.count();
	for (Vec3 p : POINTS) {
		CAPTURE(p.x, p.y, p.z);
		CHECK(tree.probability(sky, p) >= 0.25f);
		CHECK(tree.probability(sky, p) <= 0.75f);
	}
	CHECK(tree.probability(sky, Vec3{-1.3f, 2.4f, 0.6f}) < tree.probability(sky, Vec3{40.0f, 3.0f, 25.0f}));
	// Without area lights the sky is the only light.
	Scene sky_only;
	sky_only.environment = Env_Constant{Spectrum{1.0f}};
	sky_only.commit();
	CHECK(Light_Distribution(sky_only, Light_Choice::tree).probability(0, Vec3{0.0f}) == 1.0f);
}

TEST_CASE("the light tree chooses each light as often as its probability says (chi-square)", "[light_tree]") {
	Scene scene = field_of_lamps();
	Light_Distribution tree(scene, Light_Choice::tree);
	const size_t n = 400000;
	const double alpha = stats::sidak(0.01, POINTS.size());
	RNG rng(31);
	for (Vec3 p : POINTS) {
		std::vector<double> expected = probabilities(tree, scene, p), observed(expected.size(), 0.0);
		for (double& e : expected) e *= double(n);
		for (size_t k = 0; k < n; k++) observed[tree.choose(rng, p).light] += 1.0;
		stats::Chi2_Result result = stats::chi2_test(observed, expected);
		CAPTURE(p.x, p.y, p.z, result.statistic, result.dof, result.p_value, alpha);
		INFO("choose() and probability() disagree: look at Light_Tree::choose and Light_Tree::probability");
		CHECK(result.observed_in_impossible_cells == 0.0);
		CHECK(result.p_value > alpha);
	}
}

TEST_CASE("the light tree reports with each light it chooses exactly the probability it gives that light",
          "[light_tree]") {
	Scene scene = field_of_lamps();
	Light_Distribution tree(scene, Light_Choice::tree);
	RNG rng(5);
	for (Vec3 p : POINTS) {
		for (int k = 0; k < 2000; k++) {
			Light_Distribution::Choice chosen = tree.choose(rng, p);
			CAPTURE(p.x, p.y, p.z, chosen.light);
			REQUIRE(chosen.probability > 0.0f);
			REQUIRE(chosen.probability == tree.probability(chosen.light, p)); // bit for bit
		}
	}
}

TEST_CASE("light bounds never rule out a light that can light the point", "[light_tree]") {
	// A light sends light to p only if p is in front of some point of it. Then the importance of its
	// own bounds, and of any group's bounds that hold it, must not be 0, or the tree would never
	// choose it. Pairs of the field's lamps, merged, at random points.
	Scene scene = field_of_lamps();
	std::vector<double> powers = light_powers(scene);
	RNG rng(77);
	size_t lit = 0;
	for (int k = 0; k < 20000; k++) {
		size_t a = rng.integer(uint32_t(scene.area_lights.count())), b = rng.integer(uint32_t(scene.area_lights.count()));
		Light_Bounds bounds_a = light_bounds(scene.area_lights.light(a), float(powers[a]));
		Light_Bounds both = merged(bounds_a, light_bounds(scene.area_lights.light(b), float(powers[b])));
		Vec3 p{12.0f * rng.unit() - 6.0f, 8.0f * rng.unit() - 2.0f, 10.0f * rng.unit() - 5.0f};
		Area_Lights::Point on_a = scene.area_lights.sample_point(a, rng);
		if (!(glm::dot(on_a.normal, p - on_a.position) > 0.0f)) continue; // p is behind that point
		lit++;
		CAPTURE(k, a, b, p.x, p.y, p.z);
		REQUIRE(bounds_a.importance(p) > 0.0f);
		REQUIRE(both.importance(p) > 0.0f);
	}
	CHECK(lit > 5000);
}

TEST_CASE("the light tree gives 0 to a light whose back the point sees", "[light_tree]") {
	// One lamp facing down and one facing up, side by side: a point below both is lit by the first
	// alone, and the tree never spends a sample on the second; above both, the other way round.
	Scene scene;
	uint32_t lamp = add_material(scene, emitter(Spectrum{10.0f}), "lamp");
	add_object(scene, ceiling_square(0.2f, 2.0f), lamp, glm::translate(Mat4{1.0f}, Vec3{-1.0f, 0.0f, 0.0f}));
	add_object(scene, parallelogram(Vec3{0.8f, 2.0f, -0.2f}, Vec3{0.4f, 0.0f, 0.0f}, Vec3{0.0f, 0.0f, -0.4f}), lamp);
	scene.commit();
	REQUIRE(scene.area_lights.count() == 2);
	Light_Distribution tree(scene, Light_Choice::tree);
	Vec3 below{0.0f, 0.0f, 0.0f}, above{0.0f, 4.0f, 0.0f};
	CHECK(tree.probability(0, below) == 1.0f);
	CHECK(tree.probability(1, below) == 0.0f);
	CHECK(tree.probability(0, above) == 0.0f);
	CHECK(tree.probability(1, above) == 1.0f);
}

TEST_CASE("where no light faces the point, the light tree still chooses one (each as often)", "[light_tree]") {
	// Two lamps facing down, a point above both: neither can light it, yet every walk down the tree
	// must end in a light with the probability it reports, or task 6's mixture (which continues the
	// path in the direction of its light sample) would lose those paths.
	Scene scene;
	uint32_t lamp = add_material(scene, emitter(Spectrum{10.0f}), "lamp");
	for (float x : {-1.0f, 1.0f}) add_object(scene, ceiling_square(0.2f, 2.0f), lamp, glm::translate(Mat4{1.0f}, Vec3{x, 0.0f, 0.0f}));
	scene.commit();
	Light_Distribution tree(scene, Light_Choice::tree);
	Vec3 above{0.3f, 4.0f, 0.0f};
	CHECK(tree.probability(0, above) == 0.5f);
	CHECK(tree.probability(1, above) == 0.5f);
	RNG rng(8);
	for (int k = 0; k < 100; k++) REQUIRE(tree.choose(rng, above).probability == 0.5f);
}

TEST_CASE("with one light the light tree renders what choice by power renders, bit for bit", "[light_tree]") {
	// One area light (the Cornell box) or only a sky (bunny_sun): both choose it with probability 1
	// from the same random number, so the tree costs these scenes nothing but its walk's test.
	for (const char* file : {"scenes/cornell_box.json", "scenes/bunny_sun.json"}) {
		Scene scene = load_scene(file);
		Render_Settings settings = scene.settings;
		settings.width = settings.height = 16;
		settings.samples = 4;
		Estimator_Choice estimator{"nee"};
		estimator.light_choice = Light_Choice::power;
		Film by_power = render(Pathtracer(scene, settings, View::path, estimator));
		estimator.light_choice = Light_Choice::tree;
		Film by_tree = render(Pathtracer(scene, settings, View::path, estimator));
		CAPTURE(file);
		for (size_t i = 0; i < by_power.pixels.size(); i++) {
			CAPTURE(i);
			REQUIRE(std::memcmp(&by_power.pixels[i].mean, &by_tree.pixels[i].mean, sizeof(glm::dvec3)) == 0);
		}
	}
}

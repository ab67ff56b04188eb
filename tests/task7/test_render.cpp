// Task 7 grader, handout §7.5: a diffuse sphere under a constant sky. A convex object cannot see
// itself, so after one bounce every path ends in the sky: the sphere's pixels are exactly albedo * L
// (a furnace: the closed form holds), whatever the sampling, and the sky's pixels are L. Standard
// errors and the bound on the render's noise come from the judge's own render with the reference
// (student_furnaces.h).
#include "env_test_support.h"
#include "film_statistics.h"
#include "furnace_scenes.h"
#include "student_furnaces.h"

#include "lab_catch2.h"

#include <optional>

using namespace env_test;

namespace {
constexpr float DISTANCE = 3.0f, V_FOV = 45.0f;
constexpr uint32_t SIZE = 16;

// The sky's radiance and the sphere's albedo: public, or drawn from the grading seed (each channel
// of the sky in [0.1, 2], of the albedo in [0.1, 0.9]), with the render's seed.
struct Colours {
	Spectrum sky{0.25f, 0.5f, 1.0f};
	Spectrum albedo{0.8f, 0.5f, 0.2f};
	uint64_t seed = 7;
};
Colours colours() {
	Colours c;
	std::optional<RNG> secret = judge::secret_inputs();
	if (!secret) return c;
	RNG& rng = *secret;
	for (int k = 0; k < 3; k++) c.sky[k] = 0.1f + 1.9f * rng.unit(), c.albedo[k] = 0.1f + 0.8f * rng.unit();
	c.seed = uint64_t(rng.integer()) << 32 | rng.integer();
	return c;
}

// The diffuse sphere under `environment`.
Scene sphere_under(const Environment& environment, const Colours& c) {
	Furnace_Options options;
	options.environment = c.sky;
	Scene scene = sphere_seen_from_outside(diffuse_material(c.albedo), options, DISTANCE, V_FOV);
	scene.environment = environment;
	return scene;
}

// The student's render (in the subject, with the student's environment code) of the sphere, and the
// reference's (student_furnaces.h).
Furnace_Render render_sphere(const Environment& environment, const Colours& c) {
	return render_square(sphere_under(environment, c), SIZE, 64, 4, c.seed);
}

// A map whose light no closed form gives: every texel its own colour, a sky bright where it faces
// one way (public, or drawn from the grading seed).
HDR_Image probe_map() {
	std::optional<RNG> secret = judge::secret_inputs();
	HDR_Image map(16, 8);
	Vec3 towards = secret ? glm::normalize(Vec3{secret->unit(), secret->unit(), secret->unit()} - 0.5f)
	                      : glm::normalize(Vec3{1.0f, 1.0f, 0.5f});
	for (uint32_t j = 0; j < map.h; j++) {
		for (uint32_t i = 0; i < map.w; i++) {
			Vec3 dir = uv_to_direction(Vec2((i + 0.5f) / map.w, (j + 0.5f) / map.h));
			float glow = 0.2f + 3.0f * std::pow(std::max(0.0f, glm::dot(dir, towards)), 4.0f);
			Spectrum tint = secret ? Spectrum{0.5f + secret->unit(), 0.5f + secret->unit(), 0.5f + secret->unit()}
			                       : Spectrum{1.0f, 0.8f + 0.4f * float(i % 2), 1.2f - 0.4f * float(j % 2)};
			map.at(i, j) = glow * tint;
		}
	}
	return map;
}

// A probe (furnace_scenes.h): a scene no closed form answers, against the judge's render of it with
// the reference, its block means and its noise.
void check_probe(const Scene& probe, uint64_t seed, const std::string& what) {
	Furnace_Render film = render_square(probe, SIZE, 64, 4, seed);
	{
		INFO("non-finite samples in the probe's render (handout §7.4)");
		CHECK(film.film.non_finite() == 0);
	}
	if (!check_like_reference(film, judge::z_critical(PROBE_CHECKS), what)) return;
	check_noise(film, judge::significance(), what, "sample, pdf and evaluate must describe the same density (handout §7.4)");
}

void check_channels(const Furnace_Render& film, const Spectrum& expected, Pixel_Coverage::Kind kind,
                    const std::string& what) {
	Pixel_Coverage coverage(1.0f, DISTANCE, V_FOV, SIZE, SIZE);
	auto select = [&](uint32_t x, uint32_t y) { return coverage(x, y) == kind; };
	for (int c = 0; c < 3; c++) {
		Mean_Check check = compare_mean(film, c, expected[c], judge::z_critical(),
		                                what + ", " + to_string(kind) + ", channel " + std::to_string(c), select);
		INFO(check.message);
		CHECK(check.pass);
	}
}
} // namespace

TEST_CASE("a diffuse sphere under a constant Env_Map renders albedo * L", "[id:t7.render.env-map][statistical:20][estimate][task7][render][uses:Env_Map::sample][uses:Env_Map::pdf][uses:Env_Map::evaluate][uses:Uniform::sample]") {
	// The image is constant, so evaluate returns L in every direction, and with light sampling
	// (task 6) the path tracer also draws directions with Env_Map::sample and weighs them with pdf.
	Colours c = colours();
	Furnace_Render film = render_sphere(Env_Map(HDR_Image(16, 8, c.sky), true), c);
	{
		INFO("non-finite samples in the render: look for a division by a zero pdf or sin(theta) (handout §7.4)");
		CHECK(film.film.non_finite() == 0);
	}
	check_channels(film, c.sky, Pixel_Coverage::background,
	               "sky seen directly, expected L: Env_Map::evaluate of a constant image must return it (handout §7.3)");
	check_channels(film, c.albedo * c.sky,
	               Pixel_Coverage::sphere,
	               "diffuse sphere under a constant Env_Map, expected albedo * L: evaluate, sample and pdf must agree "
	               "(handout §7.3, §7.4)");
	check_noise(film, judge::significance(), "diffuse sphere under a constant Env_Map",
	            "Weights L / pdf must stay bounded: sample, pdf and evaluate must describe the same density "
	            "(handout §7.4)");
	check_probe(sphere_under(Env_Map(probe_map(), true), c), c.seed + 1,
	            "The probe (the sphere under an Env_Map whose texels all differ: no closed form, so it is compared "
	            "with the reference's render of the same scene)");
}

TEST_CASE("a diffuse sphere under Env_Constant renders albedo * L", "[id:t7.render.env-constant][statistical:17][estimate][task7][render][uses:Env_Map::sample][uses:Env_Map::pdf][uses:Env_Map::evaluate][uses:Uniform::sample]") {
	// Env_Constant samples with Samplers::Sphere::Uniform (used when the path tracer samples lights).
	Colours c = colours();
	Furnace_Render film = render_sphere(Env_Constant{c.sky}, c);
	{
		INFO("non-finite samples in the render (handout §7.2)");
		CHECK(film.film.non_finite() == 0);
	}
	check_channels(film, c.albedo * c.sky, Pixel_Coverage::sphere,
	               "diffuse sphere under Env_Constant, expected albedo * L: Uniform::sample and pdf must agree "
	               "(handout §7.2)");
	check_noise(film, judge::significance(), "diffuse sphere under Env_Constant",
	            "Uniform directions have the constant density 1 / (4 pi): sample and pdf must agree (handout §7.2)");
	std::optional<RNG> secret = judge::secret_inputs();
	check_probe(with_probe_sphere(sphere_under(Env_Constant{c.sky}, c), secret ? &*secret : nullptr), c.seed + 1,
	            "The probe (the sphere with a second one beside it under Env_Constant: no closed form, so it is "
	            "compared with the reference's render of the same scene)");
}

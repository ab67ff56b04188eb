// Task 5, handout §5.5: mirror and glass rendered with the real pipeline (render(), with the
// reference path tracer of task 4) in scenes whose answer is known in closed form.
//
// Mirror and glass samples carry weight exactly reflectance or transmittance (1 here), so under a
// uniform environment L = 1 almost every sample is exactly 1: the estimator has (nearly) zero
// variance and the bounds reduce to float rounding (FLOAT_SLACK, tests/support/film_statistics.h).
// The only exceptions are paths the depth cap cuts while still inside the glass (value 0); see the
// glass furnace below for how rare they are. Each comparison is a z-test with the film's own
// standard error plus that rounding allowance, Šidák-corrected over the file's Z_TESTS tests.
#include "film_statistics.h"
#include "furnace_scenes.h"
#include "render.h"
#include "statistics.h"

#include <catch2/catch.hpp>

#include <string>

namespace {

constexpr size_t Z_TESTS = 18; // 9 + 3 + 6, counted per TEST_CASE below
const double Z = stats::two_sided_z(stats::sidak(0.01, Z_TESTS));

void require_finite(const Film& film) {
	INFO(film.non_finite() << " samples were NaN or infinite: look at divisions in refract and fresnel "
	                          "(grazing angles, cos_theta = 0)");
	REQUIRE(film.non_finite() == 0);
}

} // namespace

TEST_CASE("Glass furnace: a clear glass sphere in a uniform environment L = 1 renders 1 (energy is conserved)") {
	// Every path through clear glass ends in the environment with weight 1, unless the depth cap
	// stops it inside. Inside a sphere the internal angle equals the refracted one, so there is no
	// total internal reflection and a path is still inside after D scattering events with
	// probability (1 - F) F^(D - 1). Averaged over the disc this is 4.7e-7 for D = 64 (anchors §4:
	// 3.9e-6 at D = 32), twenty times below FLOAT_SLACK; a cut path would also show in the standard
	// error. So a correct glass renders 1 to float precision; losing the Fresnel choice (weights F
	// and 1 - F on top of choosing by F) or absorbing light falls far outside.
	const float distance = 4.0f, fov = 40.0f;
	const uint32_t size = 32;
	const Material clear_glass = glass_material(Spectrum{1.0f}, Spectrum{1.0f}, 1.5f);
	Scene scene = sphere_seen_from_outside(clear_glass, Furnace_Options{}, distance, fov);
	Pixel_Coverage coverage(1.0f, distance, fov, size, size);
	Film film = render_square(scene, size, 64, 64, 11);
	require_finite(film);
	for (auto kind : {Pixel_Coverage::sphere, Pixel_Coverage::silhouette, Pixel_Coverage::background}) {
		auto select = [&](uint32_t x, uint32_t y) { return coverage(x, y) == kind; };
		for (int c = 0; c < 3; c++) {
			check_mean(film, c, 1.0, Z,
			           std::string("mean of the ") + to_string(kind) +
			               " (a reflection weighs the reflectance, 1, and a refraction the transmittance, 1: the "
			               "choice with probability F already accounts for Fresnel, handout §5.4)",
			           select);
		}
	}
}

TEST_CASE("Glass, seen from inside: the lab does not scale radiance by eta^2, so the view from inside a glass "
          "sphere under L = 1 is 1, not 2.25") {
	// material.h: transmitted radiance is not multiplied by eta^2. A renderer that does (radiance
	// "compresses" into the denser medium) would show 1.5^2 = 2.25 here, while the furnace above
	// cannot tell (the factors cancel on the way in and out). The camera is 3 units from the centre
	// of a sphere of radius 10, so every ray meets the surface at most asin(0.3) = 17.5 degrees from
	// the normal, below the critical angle: paths escape with probability >= 0.95 per hit and
	// max_depth 32 leaves a 0.05^32 chance of being cut.
	Furnace_Options options;
	options.radius = 10.0f;
	const Material clear_glass = glass_material(Spectrum{1.0f}, Spectrum{1.0f}, 1.5f);
	Scene scene = sphere_seen_from_inside(clear_glass, options, Vec3{3.0f, 0.0f, 0.0f}, Vec3{0.0f, 1.0f, -5.0f}, 60.0f);
	Film film = render_square(scene, 16, 32, 32, 12);
	require_finite(film);
	for (int c = 0; c < 3; c++) {
		check_mean(film, c, 1.0, Z,
		           "image mean from inside a glass sphere (2.25 = 1.5^2 would mean transmitted radiance was scaled by "
		           "eta^2, 0.44 that it was divided by it; the lab does neither, material.h and handout §5.4)");
	}
}

TEST_CASE("Mirror furnace: a mirror sphere of reflectance R in a uniform environment L = 1 renders R") {
	// A convex mirror reflects every camera ray once, straight into the environment: R * L.
	const Spectrum reflectance{0.9f, 0.5f, 0.2f};
	const float distance = 3.0f, fov = 50.0f;
	const uint32_t size = 32;
	Scene scene = sphere_seen_from_outside(mirror_material(reflectance), Furnace_Options{}, distance, fov);
	Pixel_Coverage coverage(1.0f, distance, fov, size, size);
	auto on_sphere = [&](uint32_t x, uint32_t y) { return coverage(x, y) == Pixel_Coverage::sphere; };
	auto on_sky = [&](uint32_t x, uint32_t y) { return coverage(x, y) == Pixel_Coverage::background; };
	Film film = render_square(scene, size, 16, 8, 13);
	require_finite(film);
	for (int c = 0; c < 3; c++) {
		check_mean(film, c, reflectance[c], Z,
		           std::string("mean of the ") + to_string(Pixel_Coverage::sphere) +
		               " (one reflection, weight = the reflectance; handout §5.1)",
		           on_sphere);
		check_mean(film, c, 1.0, Z, std::string("mean of the ") + to_string(Pixel_Coverage::background), on_sky);
	}
}

// Task 4, handouts §4.2-§4.4: the path-tracing estimator Pathtracer::shade, graded on scenes whose
// answer is known in closed form ("furnaces"), rendered with the real pipeline (render()).
//
// Each comparison is a z-test of an image mean against its closed form, with the standard error
// taken from the film's own per-pixel variances (tests/support/film_statistics.h). Where the
// estimator has zero variance (cosine sampling of a diffuse surface under uniform light returns
// the same value for every sample) the bound reduces to float rounding, FLOAT_SLACK. Russian
// roulette keeps the expectation, so the same bounds hold with it (its noise is in the variance).
#include "film_statistics.h"
#include "furnace_scenes.h"
#include "render.h"
#include "statistics.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

namespace {

// Every z-test of this file shares the significance level (Šidák correction over all of them).
constexpr size_t Z_TESTS = 72; // 27 + 24 + 18 + 3, counted per TEST_CASE below
const double Z = stats::two_sided_z(stats::sidak(0.01, Z_TESTS));


void require_finite(const Film& film) {
	INFO(film.non_finite() << " samples were NaN or infinite (render with --nan-map to see where). Look for "
	     "divisions by a pdf of 0 and for weights of directions that cannot be sampled (handout §4.2)");
	REQUIRE(film.non_finite() == 0);
}

} // namespace

TEST_CASE("Furnace: a white diffuse sphere in a uniform environment renders the environment, 1, everywhere") {
	// Albedo 1 and L_env = 1: whatever the path, light is neither created nor lost (anchors §4). A
	// convex object never sees itself, so this holds for every max_depth >= 1.
	const float distance = 4.0f, fov = 40.0f;
	const uint32_t size = 32;
	Scene scene = sphere_seen_from_outside(diffuse_material(Spectrum{1.0f}), Furnace_Options{}, distance, fov);
	Pixel_Coverage coverage(1.0f, distance, fov, size, size);
	for (uint32_t depth : {1u, 2u, 8u}) {
		CAPTURE(depth);
		Film film = render_square(scene, size, 256, depth, 41 + depth);
		require_finite(film);
		for (auto kind : {Pixel_Coverage::sphere, Pixel_Coverage::silhouette, Pixel_Coverage::background}) {
			std::string what = std::string("max_depth ") + std::to_string(depth) + ", mean of the " + to_string(kind) +
			                   " (albedo 1 under L = 1 neither gains nor loses light: each bounce's weight "
			                   "f |cos| / pdf is 1, handout §4.2)";
			auto select = [&](uint32_t x, uint32_t y) { return coverage(x, y) == kind; };
			for (int c = 0; c < 3; c++) check_mean(film, c, 1.0, Z, what, select);
		}
	}
}

TEST_CASE("Furnace: a diffuse sphere of albedo rho under a uniform sky L renders rho * L for max_depth >= 1, "
          "and black for max_depth 0") {
	// The sphere is convex: the first bounce sees only the sky, so its radiance is
	// integral (rho / pi) L cos = rho * L whatever max_depth >= 1. With max_depth = 0 a camera ray
	// may not scatter (pathtracer.h): the non-emitting sphere is black, the sky still L.
	const Spectrum rho{0.8f, 0.5f, 0.2f}, sky{0.5f, 1.0f, 2.0f};
	const float distance = 3.0f, fov = 50.0f;
	const uint32_t size = 32;
	Furnace_Options options;
	options.environment = sky;
	Scene scene = sphere_seen_from_outside(diffuse_material(rho), options, distance, fov);
	Pixel_Coverage coverage(1.0f, distance, fov, size, size);
	auto on_sphere = [&](uint32_t x, uint32_t y) { return coverage(x, y) == Pixel_Coverage::sphere; };
	auto on_sky = [&](uint32_t x, uint32_t y) { return coverage(x, y) == Pixel_Coverage::background; };
	for (uint32_t depth : {0u, 1u, 2u, 5u}) {
		CAPTURE(depth);
		Film film = render_square(scene, size, 256, depth, 7 + depth);
		require_finite(film);
		std::string prefix = "max_depth " + std::to_string(depth) + ", mean of the ";
		for (int c = 0; c < 3; c++) {
			double expected = depth == 0 ? 0.0 : double(rho[c]) * double(sky[c]);
			std::string why = depth == 0 ? " (max_depth 0: the camera ray's hit may not scatter, so a "
			                               "non-emitting surface is black)"
			                             : " (rho * L: one bounce reaches the sky)";
			check_mean(film, c, expected, Z, prefix + to_string(Pixel_Coverage::sphere) + why, on_sphere);
			check_mean(film, c, sky[c], Z, prefix + to_string(Pixel_Coverage::background), on_sky);
		}
	}
}

TEST_CASE("Furnace: inside an emitting diffuse sphere, max_depth D gives Le * (1 + rho + ... + rho^D)") {
	// Every ray inside a closed sphere hits it again. Each hit emits Le and reflects rho of what
	// arrives, so a path with at most D bounces carries Le * sum_{k=0..D} rho^k (anchors §4). An
	// off-by-one in the depth test shifts the answer by a whole term, e.g. D = 1 gives
	// Le (1 + rho + rho^2) instead of Le (1 + rho). D = 5 and 40 exercise Russian roulette.
	const Spectrum rho{0.5f, 0.7f, 0.3f}, le{1.0f, 0.5f, 2.0f};
	Furnace_Options options;
	options.radius = 2.0f;
	options.has_environment = false;
	options.inward_normals = true; // the sphere emits and reflects towards its centre
	const Vec3 eye{0.3f, -0.2f, 0.5f}, target{-0.4f, 0.1f, -1.0f};
	Scene scene = sphere_seen_from_inside(diffuse_material(rho, le), options, eye, target, 70.0f);
	for (uint32_t depth : {0u, 1u, 2u, 3u, 5u, 40u}) {
		CAPTURE(depth);
		Film film = render_square(scene, 24, 128, depth, 100 + depth);
		require_finite(film);
		for (int c = 0; c < 3; c++) {
			double sum = 0.0, power = 1.0;
			for (uint32_t k = 0; k <= depth; k++, power *= rho[c]) sum += power;
			double expected = le[c] * sum;
			check_mean(film, c, expected, Z,
			           "max_depth " + std::to_string(depth) + ": image mean, expected Le * sum_{k=0.." +
			               std::to_string(depth) + "} rho^k (emission of every hit, attenuated by rho per bounce; "
			               "max_depth counts bounces, handout §4.2)");
		}
	}
}

TEST_CASE("Furnace: a scene without emitters or environment renders exactly 0") {
	// No light anywhere: every path carries 0, whatever the BSDF does.
	Furnace_Options dark;
	dark.has_environment = false;
	Scene outside = sphere_seen_from_outside(diffuse_material(Spectrum{0.9f}), dark, 3.0f, 50.0f);
	dark.inward_normals = true;
	Scene inside =
		sphere_seen_from_inside(diffuse_material(Spectrum{0.9f}), dark, Vec3{0.1f}, Vec3{0.0f, 0.0f, -1.0f}, 60.0f);
	for (const Scene* scene : {&outside, &inside}) {
		Film film = render_square(*scene, 16, 16, 8, 3);
		require_finite(film);
		double largest = 0.0;
		for (const Pixel_Stats& p : film.pixels) largest = std::max({largest, p.mean.x, p.mean.y, p.mean.z});
		INFO((scene == &outside ? "a sphere seen from outside" : "the inside of a sphere")
		     << " without any light: the brightest pixel is " << largest
		     << ", expected exactly 0 (emission is material.emitted(out_dir), nothing else; handout §4.2)");
		CHECK(largest == 0.0);
	}
}

TEST_CASE("Furnace far from the origin: new rays must leave their surface at any scale (dist_bounds offset)") {
	// The same diffuse sphere as above, moved to 10^4 from the origin. Float coordinates there are
	// 10^-3 apart, so a hit point may lie that far inside the sphere: a new ray whose dist_bounds
	// start at a fixed small distance (1e-4, say) hits its own surface again, an extra "bounce"
	// that darkens the sphere. The offset must grow with |hit.position| (handout §4.2).
	const Spectrum rho{0.8f, 0.5f, 0.2f};
	const float distance = 3.0f, fov = 50.0f;
	const uint32_t size = 32;
	Furnace_Options options;
	options.center = Vec3{1e4f, -1e4f, 1e4f};
	Scene scene = sphere_seen_from_outside(diffuse_material(rho), options, distance, fov);
	Pixel_Coverage coverage(1.0f, distance, fov, size, size);
	auto on_sphere = [&](uint32_t x, uint32_t y) { return coverage(x, y) == Pixel_Coverage::sphere; };
	Film film = render_square(scene, size, 256, 2, 5);
	require_finite(film);
	for (int c = 0; c < 3; c++) {
		check_mean(film, c, rho[c], Z, "sphere centred at (1e4, -1e4, 1e4), mean of the " +
		                                std::string(to_string(Pixel_Coverage::sphere)) + " (expected rho * L_env)",
		           on_sphere);
	}
}

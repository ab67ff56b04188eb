// Task 5, handout §5.5: mirror and glass rendered with the real pipeline (render(), with the
// reference path tracer of task 4) in scenes whose answer is known in closed form, by the student's
// task 5 in the subject (student_furnaces.h). With a grading seed the placement, the colours, the
// glass furnace's index of refraction and the render seeds are drawn from it.
//
// Mirror and glass samples carry weight exactly reflectance or transmittance (1 here), so under a
// uniform environment L = 1 almost every sample is exactly 1: the estimator has (nearly) zero
// variance and the bounds reduce to float rounding (FLOAT_SLACK, tests/support/film_statistics.h).
// The only exceptions are paths the depth cap cuts while still inside the glass (value 0); see the
// glass furnace below for how rare they are. Each comparison is a z-test with the standard error of
// the judge's own render of the furnace with the reference (never the student's film) plus that
// rounding allowance, and each render may not be noisier than the reference's (paired_noise.h),
// each at the grader's level for one check (judge.h: significance).
#include "directions.h"
#include "film_statistics.h"
#include "furnace_scenes.h"
#include "judge.h"
#include "statistics.h"
#include "student_furnaces.h"

#include "lab_catch2.h"

#include <optional>
#include <string>

namespace {

void require_finite(const Furnace_Render& render) {
	INFO(render.film.non_finite() << " samples were NaN or infinite: look at divisions in refract and fresnel "
	                                 "(grazing angles, cos_theta = 0)");
	REQUIRE(render.film.non_finite() == 0);
}

// The render's noise against the reference's (one statistical check).
void check_noise(const Furnace_Render& render, const std::string& what) {
	check_noise(render, judge::significance(), what,
	            "A mirror or glass sample weighs exactly the reflectance or the transmittance: the choice with "
	            "probability F already accounts for Fresnel, so weights like 1 / F or 1 / (1 - F) on top make "
	            "fireflies (handout §5.4)");
}

// The probe of a furnace test case (furnace_scenes.h, with_probe_sphere): the furnace with a diffuse
// sphere beside or inside its sphere, seen through the mirror or the glass. No closed form gives it:
// it is compared with the judge's render of it with the reference.
void check_probe(const Scene& furnace, uint32_t size, std::optional<RNG>& secret) {
	Scene probe = with_probe_sphere(furnace, secret ? &*secret : nullptr);
	Furnace_Render render = render_square(probe, size, 256, 64, judge::seed_or_public(secret, 500));
	require_finite(render);
	if (!check_like_reference(render, judge::z_critical(PROBE_CHECKS), "The probe (this furnace with a diffuse sphere beside or inside its sphere, "
	                                     "max_depth 64: no closed form, so it is compared with the reference's render "
	                                     "of the same scene; what the mirror or glass shows of it must be right)")) {
		return;
	}
	check_noise(render, "the probe");
}

} // namespace

TEST_CASE("Glass furnace: a clear glass sphere in a uniform environment L = 1 renders 1 (energy is conserved)", "[id:t5.furnace.glass][statistical:23][estimate][uses:Glass::scatter]") {
	// Every path through clear glass ends in the environment with weight 1, unless the depth cap
	// stops it inside. Inside a sphere the internal angle equals the refracted one, so there is no
	// total internal reflection and a path is still inside after D scattering events with
	// probability (1 - F) F^(D - 1). Averaged over the disc this is 4.7e-7 for D = 64 (anchors §4:
	// 3.9e-6 at D = 32), twenty times below FLOAT_SLACK; a cut path would also show in the standard
	// error. (For the indices 1.2 to 2.4 a grading seed draws it stays below 5.1e-7.) So a correct
	// glass renders 1 to float precision; losing the Fresnel choice (weights F and 1 - F on top of
	// choosing by F) or absorbing light falls far outside.
	std::optional<RNG> secret = judge::secret_inputs();
	Outside_View view{Furnace_Options{}, 4.0f, 40.0f};
	float ior = 1.5f;
	if (secret) {
		view = random_outside_view(*secret, view.options);
		ior = task5::random_ior(*secret);
	}
	const uint32_t size = 32;
	const Material clear_glass = glass_material(Spectrum{1.0f}, Spectrum{1.0f}, ior);
	Scene scene = sphere_seen_from_outside(clear_glass, view.options, view.distance, view.v_fov);
	Pixel_Coverage coverage(view.options.radius, view.distance, view.v_fov, size, size);
	Furnace_Render render = render_square(scene, size, 64, 64, judge::seed_or_public(secret, 11));
	require_finite(render);
	for (auto kind : {Pixel_Coverage::sphere, Pixel_Coverage::silhouette, Pixel_Coverage::background}) {
		auto select = [&](uint32_t x, uint32_t y) { return coverage(x, y) == kind; };
		for (int c = 0; c < 3; c++) {
			check_mean(render, c, 1.0, judge::z_critical(),
			           std::string("mean of the ") + to_string(kind) +
			               " (a reflection weighs the reflectance, 1, and a refraction the transmittance, 1: the "
			               "choice with probability F already accounts for Fresnel, handout §5.4)",
			           select);
		}
	}
	check_noise(render, "the glass furnace");
	check_probe(scene, size, secret);
}

TEST_CASE("Glass, seen from inside: the lab does not scale radiance by eta^2, so the view from inside a glass "
          "sphere under L = 1 is 1, not 2.25", "[id:t5.furnace.glass-from-inside][statistical:17][estimate][uses:Glass::scatter]") {
	// material.h: transmitted radiance is not multiplied by eta^2. A renderer that does (radiance
	// "compresses" into the denser medium) would show 1.5^2 = 2.25 here, while the furnace above
	// cannot tell (the factors cancel on the way in and out). The camera is 3 units from the centre
	// of a sphere of radius 10, so every ray meets the surface at most asin(0.3) = 17.5 degrees from
	// the normal, below the critical angle: paths escape with probability >= 0.95 per hit and
	// max_depth 32 leaves a 0.05^32 chance of being cut. A grading seed puts the eye anywhere within
	// 0.4 radii of the centre (at most asin(0.4) = 23.6 degrees from the normal, where F = 0.044).
	std::optional<RNG> secret = judge::secret_inputs();
	Furnace_Options options;
	options.radius = 10.0f;
	Inside_View view{Vec3{3.0f, 0.0f, 0.0f}, Vec3{0.0f, 1.0f, -5.0f}, 60.0f};
	if (secret) {
		options.center = random_point(*secret, -10.0f, 10.0f);
		options.radius = 5.0f + 15.0f * secret->unit();
		view = random_inside_view(*secret, 0.4f * options.radius);
	}
	const Material clear_glass = glass_material(Spectrum{1.0f}, Spectrum{1.0f}, 1.5f);
	Scene scene = sphere_seen_from_inside(clear_glass, options, view.eye, view.target, view.v_fov);
	Furnace_Render render = render_square(scene, 16, 32, 32, judge::seed_or_public(secret, 12));
	require_finite(render);
	for (int c = 0; c < 3; c++) {
		check_mean(render, c, 1.0, judge::z_critical(),
		           "image mean from inside a glass sphere (2.25 = 1.5^2 would mean transmitted radiance was scaled by "
		           "eta^2, 0.44 that it was divided by it; the lab does neither, material.h and handout §5.4)");
	}
	check_noise(render, "the view from inside a glass sphere");
	check_probe(scene, 16, secret);
}

TEST_CASE("Mirror furnace: a mirror sphere of reflectance R in a uniform environment L = 1 renders R", "[id:t5.furnace.mirror][statistical:20][estimate][uses:Mirror::scatter]") {
	// A convex mirror reflects every camera ray once, straight into the environment: R * L.
	std::optional<RNG> secret = judge::secret_inputs();
	Spectrum reflectance{0.9f, 0.5f, 0.2f};
	Outside_View view{Furnace_Options{}, 3.0f, 50.0f};
	if (secret) {
		reflectance = random_colour(*secret, 0.05f, 1.0f);
		view = random_outside_view(*secret, view.options);
	}
	const uint32_t size = 32;
	Scene scene = sphere_seen_from_outside(mirror_material(reflectance), view.options, view.distance, view.v_fov);
	Pixel_Coverage coverage(view.options.radius, view.distance, view.v_fov, size, size);
	auto on_sphere = [&](uint32_t x, uint32_t y) { return coverage(x, y) == Pixel_Coverage::sphere; };
	auto on_sky = [&](uint32_t x, uint32_t y) { return coverage(x, y) == Pixel_Coverage::background; };
	Furnace_Render render = render_square(scene, size, 16, 8, judge::seed_or_public(secret, 13));
	require_finite(render);
	for (int c = 0; c < 3; c++) {
		check_mean(render, c, reflectance[c], judge::z_critical(),
		           std::string("mean of the ") + to_string(Pixel_Coverage::sphere) +
		               " (one reflection, weight = the reflectance; handout §5.1)",
		           on_sphere);
		check_mean(render, c, 1.0, judge::z_critical(), std::string("mean of the ") + to_string(Pixel_Coverage::background), on_sky);
	}
	check_noise(render, "the mirror furnace");
	check_probe(scene, size, secret);
}

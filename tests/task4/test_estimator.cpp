// Task 4, handouts §4.2-§4.4: the path-tracing estimator Pathtracer::shade, graded on scenes whose
// answer is known in closed form ("furnaces"), rendered with the real pipeline (render()) and the
// student's task 4 in the subject (student_furnaces.h). With a grading seed the furnaces' placement,
// albedos, radiances and render seeds are drawn from it; the closed forms hold for any of them.
//
// Each comparison is a z-test of an image mean against its closed form, with the standard error
// taken from the per-pixel variances of the judge's own render of the same furnace with the
// reference (tests/support/film_statistics.h, student_furnaces.h), never from the student's film.
// Where the estimator has zero variance the bound reduces to float rounding, FLOAT_SLACK. Russian
// roulette keeps the expectation, so the same bounds hold with it (its noise is in the variance).
// Each render may not be noisier than the reference's, pixel by pixel (the sign test,
// paired_noise.h): noise or fireflies fail every time, not by chance. A closed form can be computed
// from the request alone, without tracing: each test case ends with a probe no closed form answers
// (check_probe, furnace_scenes.h), against the judge's own render of it. Each z-test and each noise
// check is made at the grader's level for one check (judge.h: significance).
#include "film_statistics.h"
#include "judge.h"
#include "furnace_scenes.h"
#include "statistics.h"
#include "student_furnaces.h"

#include "lab_catch2.h"

#include <cmath>
#include <optional>
#include <sstream>
#include <string>

namespace {

const char* const IF_NOISY =
	"Look for weights that can grow without bound: a division by a small pdf or cosine (the weight is f |cos| / pdf, "
	"handout §4.2), and for a Russian roulette that cuts paths more often than the albedo says (handout §4.3)";

// What a self-intersection does (handout §4.2, spawn_ray.h): a new ray that starts at hit.position,
// which rounding puts on either side of the surface, hits the surface it leaves, and the path loses
// the light it would have found.
const char* const SELF_INTERSECTION =
	"a new ray that starts at hit.position hits the surface it leaves (self-intersection: rounding puts the hit point "
	"on either side of the surface), and the path loses its light there. Start every new ray with spawn_ray(hit, "
	"direction, ray.depth + 1) (spawn_ray.h), which moves its origin off the surface (handout §4.2)";

// Set when the white furnace at max_depth 1 came out too dark while the BSDF's own test cases pass:
// a path that bounces once off a convex sphere under the sky can then only lose light at that bounce,
// by a self-intersection. Later furnaces then lead with it, not with the leads a self-intersection
// also sets off there (max_depth's off-by-one, a division by a small pdf).
bool self_intersection_found = false;

bool bsdf_unit_tests_failed() {
	for (const char* bsdf : {"Lambertian::scatter", "Lambertian::evaluate", "Lambertian::pdf"}) {
		if (judge::unit_tests_failed(bsdf)) return true;
	}
	return false;
}

// Said of a furnace that is too dark while the BSDF's own test cases pass: the usual cause then.
std::string if_too_dark() {
	if (bsdf_unit_tests_failed()) return ""; // the note above names the BSDF
	return std::string("Too dark: ") + SELF_INTERSECTION;
}

// The lead for a furnace that fails after a self-intersection was found: fix that first.
std::string lead(const std::string& otherwise) {
	if (!self_intersection_found) return otherwise;
	return std::string("The white furnace above lost light at a single bounce: ") + SELF_INTERSECTION +
	       ". Fix that first: it darkens and adds noise to every furnace";
}

void require_finite(const Furnace_Render& render) {
	INFO(render.film.non_finite() << " samples were NaN or infinite (render with --nan-map to see where). Look for "
	     "divisions by a pdf of 0 and for weights of directions that cannot be sampled (handout §4.2)");
	REQUIRE(render.film.non_finite() == 0);
}

// The render's noise against the reference's (one statistical check). After a wrong mean the
// noise of a render of something else says nothing of its own: no lead then.
bool check_noise(const Furnace_Render& render, const std::string& what, bool means_ok = true) {
	return check_noise(render, judge::significance(), what,
	                   means_ok ? lead(IF_NOISY) : "Its mean is wrong too (above): fix that first, the noise follows");
}

// The probe of a furnace test case (furnace_scenes.h, with_probe_sphere): the furnace with a second
// sphere, whose image has no closed form, against the judge's render of it with the reference.
void check_probe(const Scene& furnace, uint32_t size, std::optional<RNG>& secret) {
	Scene probe = with_probe_sphere(furnace, secret ? &*secret : nullptr);
	Furnace_Render render = render_square(probe, size, 256, 5, judge::seed_or_public(secret, 500));
	require_finite(render);
	const std::string what = "The probe (this furnace with a second diffuse sphere " +
	                         std::string(furnace.environment ? "beside its sphere" : "inside it") +
	                         ", max_depth 5: no closed form, so it is compared with the reference's render of the same scene)";
	if (!check_like_reference(render, judge::z_critical(PROBE_CHECKS), what)) return;
	check_noise(render, "the probe");
}

} // namespace

TEST_CASE("Furnace: a white diffuse sphere in a uniform environment renders the environment, 1, everywhere", "[id:t4.furnace.white][statistical:43][estimate][fn:shade][uses:Lambertian::scatter][uses:Lambertian::evaluate][uses:Lambertian::pdf]") {
	// Albedo 1 and L_env = 1: whatever the path, light is neither created nor lost (anchors §4). A
	// convex object never sees itself, so this holds for every max_depth >= 1.
	std::optional<RNG> secret = judge::secret_inputs();
	Outside_View view{Furnace_Options{}, 4.0f, 40.0f};
	if (secret) view = random_outside_view(*secret, view.options);
	const uint32_t size = 32;
	Scene scene = sphere_seen_from_outside(diffuse_material(Spectrum{1.0f}), view.options, view.distance, view.v_fov);
	Pixel_Coverage coverage(view.options.radius, view.distance, view.v_fov, size, size);
	for (uint32_t depth : {1u, 2u, 8u}) {
		CAPTURE(depth);
		Furnace_Render render = render_square(scene, size, 256, depth, judge::seed_or_public(secret, 41 + depth));
		require_finite(render);
		bool means_ok = true;
		for (auto kind : {Pixel_Coverage::sphere, Pixel_Coverage::silhouette, Pixel_Coverage::background}) {
			std::string what = std::string("max_depth ") + std::to_string(depth) + ", mean of the " + to_string(kind) +
			                   " (albedo 1 under L = 1 neither gains nor loses light: each bounce's weight "
			                   "f |cos| / pdf is 1, handout §4.2)";
			auto select = [&](uint32_t x, uint32_t y) { return coverage(x, y) == kind; };
			bool too_bright = true;
			for (int c = 0; c < 3; c++) too_bright = too_bright && film_mean(render, c, select).mean > 1.0;
			if (too_bright && kind == Pixel_Coverage::sphere && !bsdf_unit_tests_failed()) {
				what += ". Too bright: shade weighs a sample by f |cos theta_in| / pdf, theta_in the angle between the "
				        "sample's NEW direction and the normal (not the arriving ray's); for this white sphere that "
				        "weight is exactly 1 (handout §4.2)";
			}
			means_ok = check_mean_rgb(render, glm::dvec3(1.0), judge::z_critical(3), what, select, if_too_dark());
			if (!means_ok && depth == 1 && kind == Pixel_Coverage::sphere && !bsdf_unit_tests_failed()) {
				bool too_dark = true;
				for (int c = 0; c < 3; c++) too_dark = too_dark && film_mean(render, c, select).mean < 1.0;
				self_intersection_found = too_dark;
			}
			if (!means_ok) break;
		}
		bool noise_ok = check_noise(render, "max_depth " + std::to_string(depth), means_ok);
		if (!means_ok || !noise_ok) return;
	}
	check_probe(scene, size, secret);
}

TEST_CASE("Furnace: a diffuse sphere of albedo rho under a uniform sky L renders rho * L for max_depth >= 1, "
          "and black for max_depth 0", "[id:t4.furnace.albedo-under-sky][statistical:41][estimate][fn:shade][uses:Lambertian::scatter][uses:Lambertian::evaluate][uses:Lambertian::pdf]") {
	// The sphere is convex: the first bounce sees only the sky, so its radiance is
	// integral (rho / pi) L cos = rho * L whatever max_depth >= 1. With max_depth = 0 a camera ray
	// may not scatter (pathtracer.h): the non-emitting sphere is black, the sky still L.
	std::optional<RNG> secret = judge::secret_inputs();
	Spectrum rho{0.8f, 0.5f, 0.2f}, sky{0.5f, 1.0f, 2.0f};
	Outside_View view{Furnace_Options{}, 3.0f, 50.0f};
	if (secret) {
		rho = random_colour(*secret, 0.05f, 0.95f);
		sky = random_colour(*secret, 0.2f, 3.0f);
		view = random_outside_view(*secret, view.options);
	}
	const uint32_t size = 32;
	view.options.environment = sky;
	Scene scene = sphere_seen_from_outside(diffuse_material(rho), view.options, view.distance, view.v_fov);
	Pixel_Coverage coverage(view.options.radius, view.distance, view.v_fov, size, size);
	auto on_sphere = [&](uint32_t x, uint32_t y) { return coverage(x, y) == Pixel_Coverage::sphere; };
	auto on_sky = [&](uint32_t x, uint32_t y) { return coverage(x, y) == Pixel_Coverage::background; };
	for (uint32_t depth : {0u, 1u, 2u, 5u}) {
		CAPTURE(depth);
		Furnace_Render render = render_square(scene, size, 256, depth, judge::seed_or_public(secret, 7 + depth));
		require_finite(render);
		std::string prefix = "max_depth " + std::to_string(depth) + ", mean of the ";
		glm::dvec3 expected = depth == 0 ? glm::dvec3(0.0) : glm::dvec3(rho) * glm::dvec3(sky);
		std::string why = depth == 0 ? " (max_depth 0: the camera ray's hit may not scatter, so a non-emitting "
		                               "surface is black: shade returns the emission alone once ray.depth >= "
		                               "settings.max_depth, handout §4.2)"
		                             : " (rho * L: one bounce reaches the sky)";
		bool sphere_ok = check_mean_rgb(render, expected, judge::z_critical(3), prefix + to_string(Pixel_Coverage::sphere) + why,
		                                on_sphere, if_too_dark());
		bool sky_ok = check_mean_rgb(render, glm::dvec3(sky), judge::z_critical(3), prefix + to_string(Pixel_Coverage::background), on_sky);
		bool noise_ok = check_noise(render, "max_depth " + std::to_string(depth), sphere_ok && sky_ok);
		if (!sphere_ok || !sky_ok || !noise_ok) return;
	}
	check_probe(scene, size, secret);
}

TEST_CASE("Furnace: inside an emitting diffuse sphere, max_depth D gives Le * (1 + rho + ... + rho^D)", "[id:t4.furnace.emitting-inside][statistical:37][estimate][fn:shade][uses:Lambertian::scatter][uses:Lambertian::evaluate][uses:Lambertian::pdf]") {
	// Every ray inside a closed sphere hits it again. Each hit emits Le and reflects rho of what
	// arrives, so a path with at most D bounces carries Le * sum_{k=0..D} rho^k (anchors §4). An
	// off-by-one in the depth test shifts the answer by a whole term, e.g. D = 1 gives
	// Le (1 + rho + rho^2) instead of Le (1 + rho). D = 5 and 40 exercise Russian roulette.
	std::optional<RNG> secret = judge::secret_inputs();
	Spectrum rho{0.5f, 0.7f, 0.3f}, le{1.0f, 0.5f, 2.0f};
	Furnace_Options options;
	options.radius = 2.0f;
	options.has_environment = false;
	options.inward_normals = true; // the sphere emits and reflects towards its centre
	Inside_View view{Vec3{0.3f, -0.2f, 0.5f}, Vec3{-0.4f, 0.1f, -1.0f}, 70.0f};
	if (secret) {
		rho = random_colour(*secret, 0.1f, 0.8f);
		le = random_colour(*secret, 0.2f, 2.0f);
		options.center = random_point(*secret, -10.0f, 10.0f);
		options.radius = 1.0f + 2.0f * secret->unit();
		view = random_inside_view(*secret, 0.5f * options.radius);
	}
	Scene scene = sphere_seen_from_inside(diffuse_material(rho, le), options, view.eye, view.target, view.v_fov);
	for (uint32_t depth : {0u, 1u, 2u, 3u, 5u, 40u}) {
		CAPTURE(depth);
		Furnace_Render render = render_square(scene, 24, 128, depth, judge::seed_or_public(secret, 100 + depth));
		require_finite(render);
		glm::dvec3 expected;
		for (int c = 0; c < 3; c++) {
			double sum = 0.0, power = 1.0;
			for (uint32_t k = 0; k <= depth; k++, power *= rho[c]) sum += power;
			expected[c] = le[c] * sum;
		}
		// Which lead fits: max_depth 0 and 1 right (a failure ends the loop, so a deeper depth means they
		// passed) but a deeper one wrong is how a Russian roulette that does not divide by q shows
		// (handout §4.3); otherwise the depth test or the emission (§4.2).
		std::string count_lead = depth >= 2 ? "; max_depth 0 and 1 came out right: if shade plays Russian roulette, a "
		                                      "path that continues with probability q must be divided by q (handout "
		                                      "§4.3), else check that max_depth counts bounces (handout §4.2)"
		                                    : "; max_depth counts bounces, handout §4.2";
		bool mean_ok = check_mean_rgb(render, expected, judge::z_critical(3),
		                              "max_depth " + std::to_string(depth) + ": image mean, expected Le * sum_{k=0.." +
		                                  std::to_string(depth) + "} rho^k (shade adds the emission material.emitted of "
		                                  "every hit, attenuated by rho per bounce" +
		                                  (self_intersection_found ? "" : count_lead) + ")",
		                              every_pixel, lead(""));
		bool noise_ok = check_noise(render, "max_depth " + std::to_string(depth), mean_ok);
		if (!mean_ok || !noise_ok) return;
	}
	check_probe(scene, 24, secret);
}

TEST_CASE("Furnace: a scene without emitters or environment renders exactly 0", "[id:t4.furnace.no-light][fn:shade][uses:Lambertian::scatter][uses:Lambertian::evaluate][uses:Lambertian::pdf]") {
	// No light anywhere: every path carries 0, whatever the BSDF does.
	std::optional<RNG> secret = judge::secret_inputs();
	Spectrum albedo{0.9f};
	Outside_View view{Furnace_Options{}, 3.0f, 50.0f};
	view.options.has_environment = false;
	Inside_View inside_view{Vec3{0.1f}, Vec3{0.0f, 0.0f, -1.0f}, 60.0f};
	if (secret) {
		albedo = random_colour(*secret, 0.05f, 1.0f);
		view = random_outside_view(*secret, view.options);
		inside_view = random_inside_view(*secret, 0.5f * view.options.radius);
	}
	Scene outside = sphere_seen_from_outside(diffuse_material(albedo), view.options, view.distance, view.v_fov);
	Furnace_Options dark = view.options;
	dark.inward_normals = true;
	Scene inside = sphere_seen_from_inside(diffuse_material(albedo), dark, inside_view.eye, inside_view.target,
	                                       inside_view.v_fov);
	for (const Scene* scene : {&outside, &inside}) {
		Furnace_Render render = render_square(*scene, 16, 16, 8, judge::seed_or_public(secret, 3));
		require_finite(render);
		double largest = 0.0;
		for (const Pixel_Stats& p : render.film.pixels) largest = std::max({largest, p.mean.x, p.mean.y, p.mean.z});
		INFO((scene == &outside ? "a sphere seen from outside" : "the inside of a sphere")
		     << " without any light: the brightest pixel is " << largest
		     << ", expected exactly 0 (emission is material.emitted(out_dir), nothing else; handout §4.2)");
		CHECK(largest == 0.0);
	}
}

TEST_CASE("Furnace far from the origin: new rays must leave their surface at any scale (spawn_ray)", "[id:t4.furnace.far-from-origin][statistical:17][estimate][fn:shade][uses:Lambertian::scatter][uses:Lambertian::evaluate][uses:Lambertian::pdf]") {
	// The same diffuse sphere as above, moved to 10^4 from the origin. Float coordinates there are
	// 10^-3 apart, so a hit point may lie that far inside the sphere: a new ray whose dist_bounds
	// start at a fixed small distance (1e-4, say) hits its own surface again, an extra "bounce"
	// that darkens the sphere. The offset must grow with |hit.position| (handout §4.2).
	std::optional<RNG> secret = judge::secret_inputs();
	Spectrum rho{0.8f, 0.5f, 0.2f};
	Outside_View view{Furnace_Options{}, 3.0f, 50.0f};
	view.options.center = Vec3{1e4f, -1e4f, 1e4f};
	std::string centre = "(1e4, -1e4, 1e4)";
	if (secret) {
		// Every coordinate's magnitude in [8192, 16384), where floats are 2^-10 ~ 1e-3 apart. The
		// distance is a multiple of 2^-10 too, so that the camera sits exactly where Pixel_Coverage
		// assumes.
		rho = random_colour(*secret, 0.05f, 0.95f);
		view = random_outside_view(*secret, view.options);
		view.distance = std::round(view.distance * 1024.0f) / 1024.0f;
		for (int i = 0; i < 3; i++) {
			view.options.center[i] = (secret->coin_flip(0.5f) ? 1.0f : -1.0f) * (8192.0f + 8000.0f * secret->unit());
		}
		std::ostringstream text;
		text << "(" << view.options.center.x << ", " << view.options.center.y << ", " << view.options.center.z << ")";
		centre = text.str();
	}
	const uint32_t size = 32;
	Scene scene = sphere_seen_from_outside(diffuse_material(rho), view.options, view.distance, view.v_fov);
	Pixel_Coverage coverage(view.options.radius, view.distance, view.v_fov, size, size);
	auto on_sphere = [&](uint32_t x, uint32_t y) { return coverage(x, y) == Pixel_Coverage::sphere; };
	Furnace_Render render = render_square(scene, size, 256, 2, judge::seed_or_public(secret, 5));
	require_finite(render);
	bool mean_ok = check_mean_rgb(render, glm::dvec3(rho), judge::z_critical(3),
	                              "sphere centred at " + centre + ", mean of the " +
	                                  std::string(to_string(Pixel_Coverage::sphere)) + " (expected rho * L_env)",
	                              on_sphere, if_too_dark());
	bool noise_ok = check_noise(render, "sphere centred at " + centre, mean_ok);
	if (mean_ok && noise_ok) check_probe(scene, size, secret);
}

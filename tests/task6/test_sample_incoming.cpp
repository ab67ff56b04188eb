// Task 6 grader, part 1: what Pathtracer::sample_incoming returns, sample by sample (handout §6.2,
// §6.3): the mixture's density for the direction it returns, a fair coin between the strategies,
// discrete BSDFs and light-less scenes left to BSDF sampling, and no NaN where no strategy can
// produce a direction. The student's samples come in one request per test case; the expected
// densities are the reference BSDF's and the framework's light sampler's.
#include "direct_lighting_estimators.h"
#include "frame.h"
#include "judge.h"
#include "light_closed_forms.h"
#include "light_scenes.h"
#include "statistics.h"
#include "task6_inputs.h"

#include "lab_catch2.h"

#include <cmath>
#include <sstream>

using namespace task6;

namespace {

const BSDF GREY{BSDF_Lambertian{Spectrum{0.5f}}};

std::string describe(Vec3 v) {
	std::ostringstream out;
	out << "(" << v.x << ", " << v.y << ", " << v.z << ")";
	return out.str();
}

// The first disagreement found among many samples, in words (empty if none).
struct First_Problem {
	std::string text;
	size_t count = 0;
	void note(const std::string& what) {
		if (count++ == 0) text = what;
	}
};

// The student's samples at the lit point under the ceiling light of `scene`.
std::vector<Incoming_Sample> samples_at(const Scene& scene, const Lit_Point& lit, size_t n, uint64_t seed) {
	return student_samples(scene, surface_point(lit.position, lit.normal), GREY, lit.out_dir, n, seed);
}

// Checks every sample of sample_incoming against the mixture's definition.
First_Problem check_mixture_samples(const Pathtracer& pt, const Lit_Point& lit,
                                    const std::vector<Incoming_Sample>& samples) {
	First_Problem problem;
	Frame frame = Frame::from_normal(lit.normal);
	Vec3 out_local = frame.to_local(lit.out_dir);
	for (size_t i = 0; i < samples.size(); i++) {
		const Incoming_Sample& s = samples[i];
		std::string where = "sample " + std::to_string(i) + ", direction " + describe(s.direction) + ": ";
		if (!is_finite(s.direction) || std::abs(glm::length(s.direction) - 1.0f) > 1e-4f) {
			problem.note(where + "the direction must be a unit vector (handout §6.3)");
			continue;
		}
		if (s.discrete) {
			problem.note(where + "a Lambertian sample is not discrete");
			continue;
		}
		Vec3 in_local = frame.to_local(s.direction);
		float expected = 0.5f * GREY.pdf(out_local, in_local) + 0.5f * pt.area_lights_pdf(lit.position, s.direction);
		if (!(std::abs(s.pdf - expected) <= 1e-4f * expected + 1e-6f)) {
			problem.note(where + "pdf " + std::to_string(s.pdf) + ", but 0.5 * bsdf.pdf + 0.5 * area_lights_pdf = " +
			             std::to_string(expected) +
			             ". Whichever strategy drew the direction, its density is the mixture's, with both pdfs "
			             "of the same direction: the BSDF's in the local frame, the lights' in world space "
			             "(handout §6.2, §6.3)");
			continue;
		}
		// The side of a grazing direction is decided by rounding: compare only clear cases.
		Spectrum f = GREY.evaluate(out_local, in_local);
		if (std::abs(in_local.y) > 1e-5f && expected > 0.0f && glm::length(s.attenuation - f) > 1e-5f) {
			problem.note(where + "attenuation " + describe(s.attenuation) + ", but bsdf.evaluate(out, in) = " +
			             describe(f) + " (handout §6.2)");
		}
	}
	return problem;
}

} // namespace

TEST_CASE("sample_incoming returns the mixture's density 0.5 bsdf.pdf + 0.5 area_lights_pdf of its direction",
          "[id:t6.mixture.density][task6][fn:sample_incoming]") {
	Lit_Point lit = lit_point();
	SECTION("a square light") {
		Scene scene = ceiling_light_scene(lit.half_side, lit.height);
		Pathtracer pt(scene, Render_Settings{});
		First_Problem problem =
			check_mixture_samples(pt, lit, samples_at(scene, lit, 20000, judge::secret_seed_or(1)));
		INFO("sample_incoming at a lit point under a square light: " << problem.count << " of 20000 samples wrong. "
		                                                             << problem.text);
		CHECK(problem.count == 0);
	}
	SECTION("a square light and a constant environment") {
		Scene scene = ceiling_light_scene(lit.half_side, lit.height);
		scene.environment = Env_Constant{Spectrum{0.2f}};
		Pathtracer pt(scene, Render_Settings{});
		First_Problem problem = check_mixture_samples(
			pt, lit, samples_at(scene, lit, 20000, judge::secret_seed_or(2)));
		INFO("sample_incoming under a square light and an environment: " << problem.count << " of 20000 samples "
		                                                                 << "wrong. " << problem.text);
		CHECK(problem.count == 0);
	}
}

TEST_CASE("sample_incoming chooses BSDF or light sampling with a fair coin", "[id:t6.mixture.fair-coin][statistical:1][task6][fn:sample_incoming]") {
	// Light sampling always aims at the light; cosine-weighted BSDF sampling hits it with
	// probability E / (pi L) (the irradiance of a light of radiance 1, over pi). So a fair coin sends
	// a fraction 1/2 + 1/2 * E / pi of the directions towards the light.
	Lit_Point lit = lit_point();
	Scene scene = ceiling_light_scene(lit.half_side, lit.height);
	Pathtracer pt(scene, Render_Settings{});
	double e = closed_form::polygon_irradiance(ceiling_square_corners(lit.half_side, lit.height),
	                                           glm::dvec3(lit.position), glm::dvec3(lit.normal), 1.0);
	double expected = 0.5 + 0.5 * e / M_PI;

	const size_t n = 100000;
	size_t towards_light = 0;
	for (const Incoming_Sample& s : samples_at(scene, lit, n, judge::secret_seed_or(3))) {
		if (pt.area_lights_pdf(lit.position, s.direction) > 0.0f) towards_light++;
	}
	double z = stats::binomial_z(towards_light, n, expected), critical = judge::z_critical();
	INFO("sample_incoming sent " << towards_light << " of " << n << " directions towards the light; a fair coin "
	                             << "between BSDF and light sampling sends " << expected * n << " (z = " << z
	                             << ", critical " << critical << "). Flip rng.coin_flip(0.5f) and "
	                             << "use sample_area_lights on one side (handout §6.2)");
	CHECK(std::abs(z) <= critical);
}

TEST_CASE("discrete BSDFs are sampled as they are, without light sampling", "[id:t6.mixture.discrete-bsdf][task6][fn:sample_incoming]") {
	Lit_Point lit = lit_point();
	Scene scene = ceiling_light_scene(lit.half_side, lit.height);
	Trace hit = surface_point(lit.position, lit.normal);
	Frame frame = Frame::from_normal(lit.normal);
	Vec3 out_local = frame.to_local(lit.out_dir);
	uint64_t seed = judge::secret_seed_or(4);

	SECTION("a mirror reflects, always") {
		BSDF mirror_bsdf{BSDF_Mirror{Spectrum{0.9f, 0.8f, 0.7f}}};
		RNG any(0);
		Scatter expected = mirror_bsdf.scatter(any, out_local);
		Vec3 reflection = frame.to_world(expected.direction);
		std::vector<Incoming_Sample> samples = student_samples(scene, hit, mirror_bsdf, lit.out_dir, 1000, seed);
		for (size_t i = 0; i < samples.size(); i++) {
			const Incoming_Sample& s = samples[i];
			INFO("sample " << i << ": a mirror's sample must be its BSDF sample, marked discrete: direction "
			               << describe(s.direction) << " (expected " << describe(reflection) << "), attenuation "
			               << describe(s.attenuation) << " (expected " << describe(expected.attenuation)
			               << "), discrete " << s.discrete
			               << ". sample_incoming must check bsdf.is_discrete() first (handout §6.2)");
			REQUIRE(s.discrete);
			REQUIRE(glm::length(s.direction - reflection) <= 1e-5f);
			REQUIRE(glm::length(s.attenuation - expected.attenuation) <= 1e-6f);
		}
	}
	SECTION("glass reflects or refracts") {
		BSDF glass_bsdf{BSDF_Glass{Spectrum{1.0f}, Spectrum{1.0f}, 1.5f}};
		bool internal = false;
		Vec3 reflection = frame.to_world(reflect(out_local));
		Vec3 refraction = frame.to_world(refract(out_local, 1.5f, internal));
		std::vector<Incoming_Sample> samples = student_samples(scene, hit, glass_bsdf, lit.out_dir, 1000, seed);
		for (size_t i = 0; i < samples.size(); i++) {
			const Incoming_Sample& s = samples[i];
			bool reflected = glm::length(s.direction - reflection) <= 1e-5f;
			bool refracted = glm::length(s.direction - refraction) <= 1e-5f;
			INFO("sample " << i << ": glass must give its own BSDF sample (the reflection " << describe(reflection)
			               << " or the refraction " << describe(refraction) << "), marked discrete; got "
			               << describe(s.direction) << ", discrete " << s.discrete << " (handout §6.2)");
			REQUIRE(s.discrete);
			REQUIRE((reflected || refracted));
		}
	}
}

TEST_CASE("without lights, sample_incoming is plain BSDF sampling", "[id:t6.mixture.no-lights][task6][fn:sample_incoming]") {
	// A grey sphere and nothing that emits: has_lights() is false, and sample_area_lights would throw.
	Scene scene;
	add_object(scene, Sphere{1.0f}, add_material(scene, diffuse_material(Spectrum{0.5f}), "grey"));
	scene.commit();
	Pathtracer pt(scene, Render_Settings{});
	REQUIRE_FALSE(pt.has_lights());

	Lit_Point lit = lit_point();
	Trace hit = surface_point(Vec3{0.0f, 1.0f, 0.0f}, lit.normal);
	Frame frame = Frame::from_normal(lit.normal);
	Vec3 out_local = frame.to_local(lit.out_dir);
	uint64_t seed = judge::secret_seed_or(5);
	std::vector<Incoming_Sample> samples;
	{
		INFO("a scene without lights: check has_lights() before sampling the lights (handout §6.2)");
		REQUIRE_NOTHROW(samples = student_samples(scene, hit, GREY, lit.out_dir, 1000, seed));
	}
	for (size_t i = 0; i < samples.size(); i++) {
		const Incoming_Sample& s = samples[i];
		float bsdf_pdf = GREY.pdf(out_local, frame.to_local(s.direction));
		INFO("sample " << i << ": pdf " << s.pdf << ", but without lights the density is the BSDF's alone, "
		               << bsdf_pdf << " (no mixture: nothing to mix with)");
		REQUIRE(s.pdf == Approx(bsdf_pdf).epsilon(1e-4).margin(1e-6));
	}
}

TEST_CASE("a direction no strategy can produce carries zero weight, never NaN", "[id:t6.mixture.zero-weight][task6][fn:sample_incoming]") {
	// A light lying in the receiver's own plane, seen exactly edge-on: its directions are on the
	// horizon (BSDF density 0) and graze the light (light density 0), so the mixture density is 0.
	// With a grading seed the light's place in the plane and out_dir are drawn.
	Vec3 corner{1.0f, 0.0f, -0.5f}, side{0.0f, 0.0f, 1.0f}, depth{1.0f, 0.0f, 0.0f};
	Vec3 out_dir = glm::normalize(Vec3{0.3f, 1.0f, 0.2f});
	if (std::optional<RNG> secret = judge::secret_inputs()) {
		RNG& rng = *secret;
		float angle = 2.0f * PI_F * rng.unit(), distance = 0.5f + rng.unit(), width = 0.5f + rng.unit();
		Vec3 away{std::cos(angle), 0.0f, std::sin(angle)}, across{-away.z, 0.0f, away.x};
		corner = distance * away - 0.5f * width * across;
		side = width * across;
		depth = (0.5f + rng.unit()) * away;
		out_dir = direction_in_cone(rng, Vec3{0.0f, 1.0f, 0.0f}, 0.3f);
	}
	Scene scene;
	add_object(scene, parallelogram(corner, side, depth), add_material(scene, emitter(Spectrum{1.0f}), "light"));
	scene.commit();
	Trace hit = surface_point(Vec3{0.0f}, Vec3{0.0f, 1.0f, 0.0f});
	std::vector<Incoming_Sample> samples =
		student_samples(scene, hit, GREY, out_dir, 2000, judge::secret_seed_or(6));
	size_t zero_pdf = 0;
	for (size_t i = 0; i < samples.size(); i++) {
		const Incoming_Sample& s = samples[i];
		if (s.pdf == 0.0f) zero_pdf++;
		INFO("sample " << i << ": pdf " << s.pdf << ", attenuation " << describe(s.attenuation)
		               << ". A direction of density 0 must come with zero attenuation, and nothing may be NaN "
		               << "(handout §6.2)");
		REQUIRE(std::isfinite(s.pdf));
		REQUIRE(is_finite(s.attenuation));
		REQUIRE((s.pdf > 0.0f || s.attenuation == Spectrum{0.0f}));
	}
	// About half the samples come from the light: the case must actually have been exercised.
	INFO("only " << zero_pdf << " of 2000 samples had density 0: were the lights sampled at all? (handout §6.2)");
	CHECK(zero_pdf > 0);
}

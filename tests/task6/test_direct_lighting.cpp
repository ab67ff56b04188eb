// Task 6 grader, part 2: what the mixture estimates (handout §6.1, §6.2, §6.4). Closed forms for the
// light a diffuse surface reflects (Lambert's formula for a square light, pi L (r/d)^2 cos(beta) for a
// sphere), the three strategies agreeing on them, the variance the mixture saves under a small
// light, and full renders with max_depth 1. The student's sample_incoming and trace_pixel answer
// in one request per estimate; the other strategies are the grader's own.
//
// The student's estimates are z-tested with the standard error of the REFERENCE's estimator (the
// judge's own samples of the reference mixture, as many as the student's with another seed),
// never the student's own, and the student's samples may not be noisier than the reference's
// (the sign test on the variances of 50 batches of each, paired_noise.h: exact for any law of the
// samples). As many samples are enough: the reference's variance is then off by sqrt((κ - 1) / n)
// relative, κ the samples' kurtosis (measured over 4e5 samples of the reference: 1.3 at the lit
// point, 8 under the sphere light, 1.3 and 2.0 for the two floors), so under 1 % for n >= 5e4, and
// the standard error by under 0.5 %, which moves the z-test's threshold by as much.
#include "direct_lighting_estimators.h"
#include "film_statistics.h"
#include "judge.h"
#include "light_closed_forms.h"
#include "light_scenes.h"
#include "statistics.h"
#include "task6_inputs.h"

#include "lab_catch2.h"
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

using namespace task6;

namespace {

const float RHO = 0.5f; // albedo of every receiver
const BSDF GREY{BSDF_Lambertian{Spectrum{RHO}}};

std::vector<double> samples_from(const Scene& scene, const Trace& point, const std::vector<Incoming_Sample>& drawn) {
	std::vector<double> samples;
	for (const Incoming_Sample& s : drawn) samples.push_back(reflected_radiance_sample(scene, point, s));
	return samples;
}

// n samples of the light reflected at `point` towards out_dir with one of the grader's strategies.
std::vector<double> estimate(const Pathtracer& pt, Strategy strategy, const Trace& point, Vec3 out_dir, size_t n,
                             uint64_t seed) {
	std::vector<Incoming_Sample> drawn(n);
	RNG rng(seed);
	for (Incoming_Sample& s : drawn) s = draw(pt, strategy, rng, point, GREY, out_dir);
	return samples_from(pt.scene, point, drawn);
}

// The same with the student's sample_incoming (the mixture), in one request.
std::vector<double> estimate_mixture(const Scene& scene, const Trace& point, Vec3 out_dir, size_t n, uint64_t seed) {
	return samples_from(scene, point, student_samples(scene, point, GREY, out_dir, n, seed));
}

// The reference's samples of an estimate: another stream than the student's.
uint64_t reference_seed(uint64_t seed) {
	return seed ^ 0xa5a5a5a5a5a5a5a5ull;
}

// z-test of the grader's own estimator (the reference's) against the closed form, with its own
// standard error.
void check_own_estimate(const Sample_Moments& m, double expected, const std::string& what) {
	double z = (m.mean - expected) / m.standard_error(), critical = judge::z_critical();
	INFO(what << ": estimated " << m.mean << " +- " << m.standard_error() << " (" << m.n << " samples), closed form "
	          << expected << ", z = " << z << " (critical " << critical << ")");
	CHECK(std::abs(z) <= critical);
}

// The student's estimate against the closed form: the student's noise against the reference's, and
// a z-test with the reference's standard error (two checks). The noise first: a noisier estimator's
// mean wanders beyond the reference's standard error too, and the message says so.
void check_estimate(const std::vector<double>& student_samples, const std::vector<double>& reference_samples,
                    double expected, const std::string& what, const std::string& if_biased = "") {
	Paired_Noise noise = compare_noise(student_samples, reference_samples, judge::significance());
	{
		INFO(what << ": too noisy: " << describe(noise, "batch") << ". Under a small light, light sampling "
		          "is what keeps the noise down: a fair coin between the strategies, and the mixture's pdf for every "
		          "direction (handout §6.1, §6.2)");
		CHECK(noise.pass);
	}
	Sample_Moments student = moments(student_samples), reference = moments(reference_samples);
	double error = standard_error(reference, student.n);
	double z = (student.mean - expected) / error, critical = judge::z_critical();
	INFO(what << ": estimated " << student.mean << " +- " << error << " (" << student.n
	          << " samples; the standard error of the reference's estimator), closed form " << expected << ", z = "
	          << z << " (critical " << critical << ")"
	          << (noise.pass ? if_biased : "; your estimator is noisier than the reference's (above), so its mean "
	                                     "strays further"));
	CHECK(std::abs(z) <= critical);
}

// A closed-form test case's probe (DESIGN.md, decided point 7): its scene with a black blocker that
// hides part of the light from the receiver, so that no closed form the request reveals gives the
// light that arrives. The student's estimate is z-tested against the reference's own estimate of it
// (the difference of two means: the reference's variance over each one's samples), and its noise
// against the reference's (two checks).
void check_probe(const std::vector<double>& student_samples, const std::vector<double>& reference_samples,
                 const std::string& what) {
	Paired_Noise noise = compare_noise(student_samples, reference_samples, judge::significance());
	{
		INFO(what << ": too noisy: " << describe(noise, "batch") << " (handout §6.1, §6.2)");
		CHECK(noise.pass);
	}
	Sample_Moments student = moments(student_samples), reference = moments(reference_samples);
	double error = std::sqrt(reference.variance / double(student.n) + reference.variance / double(reference.n));
	// Float rounding allowed as the furnaces allow it (film_statistics.h, FLOAT_SLACK).
	double critical = judge::z_critical();
	double allowed = critical * error + FLOAT_SLACK * std::max(1.0, std::abs(reference.mean));
	INFO(what << ": estimated " << student.mean << ", the reference's estimate " << reference.mean << " +- " << error
	          << " (" << student.n << " samples each; allowed difference " << allowed << " = " << critical
	          << " standard errors + float rounding). A blocker hides part of the light: light sampling must aim "
	             "only at what the light sends, and a sample whose ray is blocked carries no light (handout §6.2)");
	CHECK(std::abs(student.mean - reference.mean) <= allowed);
}

// A black square of half-side `half_side`, parallel to the ceiling lights, centred at `centre`.
void add_blocker(Scene& scene, Vec3 centre, float half_side) {
	add_object(scene, ceiling_square(half_side, 0.0f), add_material(scene, diffuse_material(Spectrum{0.0f}), "blocker"),
	           glm::translate(Mat4{1.0f}, centre));
}

// n camera samples of pixel (0, 0), with the film's per-sample RNG, from the student's renderer
// (trace_pixel with the student's sample_incoming) in one request.
std::vector<Spectrum> render_samples(const Scene& scene, const Render_Settings& settings, size_t n) {
	protocol::Trace_Pixels request{scene, settings, Estimator_Choice{}, View::path, {}};
	for (size_t i = 0; i < n; i++) request.samples.push_back({0, 0, RNG_State::of(RNG::for_sample(settings.seed, 0, i))});
	return judge::ask(request);
}

// The same samples from the reference's renderer, in the judge, with another seed.
std::vector<Spectrum> reference_render_samples(const Scene& scene, Render_Settings settings, size_t n) {
	settings.seed = reference_seed(settings.seed);
	Pathtracer pt(scene, settings);
	std::vector<Spectrum> values(n);
	for (size_t i = 0; i < n; i++) {
		RNG rng = RNG::for_sample(settings.seed, 0, i);
		values[i] = pt.trace_pixel(0, 0, rng);
	}
	return values;
}

std::vector<double> channel_averages(const std::vector<Spectrum>& values) {
	std::vector<double> samples;
	for (Spectrum v : values) samples.push_back((double(v.r) + double(v.g) + double(v.b)) / 3.0);
	return samples;
}

// A 1 x 1 film that sees only the floor of lit_floor (light_scenes.h).
Render_Settings one_pixel(uint64_t seed) {
	Render_Settings settings;
	settings.width = settings.height = 1;
	settings.max_depth = 1; // direct light only
	settings.seed = seed;
	return settings;
}

} // namespace

TEST_CASE("BSDF sampling, light sampling and the mixture all estimate the light Lambert's formula gives",
          "[id:t6.lighting.lambert][statistical:6][estimate][task6][uses:sample_incoming]") {
	// A tilted, off-centre receiver under a square light (public: half-side 0.5, height 1, radiance
	// 1): L_o = rho E / pi, E from Lambert's formula for polygons.
	Lit_Point lit = lit_point();
	Scene scene = ceiling_light_scene(lit.half_side, lit.height);
	Pathtracer pt(scene, Render_Settings{});
	double e = closed_form::polygon_irradiance(ceiling_square_corners(lit.half_side, lit.height),
	                                           glm::dvec3(lit.position), glm::dvec3(lit.normal), 1.0);
	double expected = RHO * e / M_PI;
	Trace point = surface_point(lit.position, lit.normal);

	uint64_t bsdf_seed = judge::secret_seed_or(11);
	uint64_t lights_seed = judge::secret_seed_or(12);
	uint64_t mixture_seed = judge::secret_seed_or(13);
	check_own_estimate(moments(estimate(pt, Strategy::bsdf, point, lit.out_dir, 100000, bsdf_seed)), expected,
	                   "BSDF sampling alone (the grader's own estimator: a failure here is a framework bug)");
	check_own_estimate(moments(estimate(pt, Strategy::lights, point, lit.out_dir, 100000, lights_seed)), expected,
	                   "light sampling alone (the grader's own estimator: a failure here is a framework bug)");
	check_estimate(estimate_mixture(scene, point, lit.out_dir, 100000, mixture_seed),
	               estimate(pt, Strategy::mixture, point, lit.out_dir, 100000, reference_seed(mixture_seed)), expected,
	               "sample_incoming's mixture, weighted attenuation * |cos| / pdf",
	               ": a biased mean means the pdf does not match how the direction was drawn (handout §6.2)");

	// The probe: a blocker half way up, off to one side of the receiver.
	Scene probe;
	add_object(probe, ceiling_square(lit.half_side, lit.height), add_material(probe, emitter(Spectrum{1.0f}), "light"));
	add_blocker(probe, lit.position + 0.5f * (lit.height - lit.position.y) * Vec3{0.0f, 1.0f, 0.0f} +
	                       Vec3{0.4f * lit.half_side, 0.0f, 0.0f},
	            0.4f * lit.half_side);
	probe.commit();
	uint64_t probe_seed = judge::secret_seed_or(14);
	check_probe(estimate_mixture(probe, point, lit.out_dir, 100000, probe_seed),
	            estimate(Pathtracer(probe, Render_Settings{}), Strategy::mixture, point, lit.out_dir, 100000,
	                     reference_seed(probe_seed)),
	            "the probe, this lit point with a blocker hiding part of the light");
}

TEST_CASE("the mixture estimates the light from a sphere: E = pi L (r/d)^2 cos(beta)", "[id:t6.lighting.sphere-light][statistical:4][estimate][task6][uses:sample_incoming]") {
	// A sphere light of radius 0.5 at distance 2 along a direction 30 degrees from the normal. With a
	// grading seed: radius 0.3 to 0.6, distance 1.5 to 3, 0 to 55 degrees from the normal, so that
	// the whole sphere stays above the horizon (beta + asin(r / d) < 79 degrees).
	double radius = 0.5, distance = 2.0, beta = M_PI / 6.0;
	if (std::optional<RNG> secret = judge::secret_inputs()) {
		RNG& rng = *secret;
		radius = 0.3 + 0.3 * rng.unit(), distance = 1.5 + 1.5 * rng.unit(), beta = glm::radians(55.0 * rng.unit());
	}
	Scene scene;
	add_object(scene, Sphere{float(radius)}, add_material(scene, emitter(Spectrum{1.0f}), "light"),
	           glm::translate(Mat4{1.0f}, Vec3{0.0f, float(distance), 0.0f}));
	scene.commit();
	Vec3 normal{float(std::sin(beta)), float(std::cos(beta)), 0.0f};
	double expected = RHO * closed_form::sphere_irradiance(radius, distance, std::cos(beta), 1.0) / M_PI;
	Trace point = surface_point(Vec3{0.0f}, normal);
	uint64_t seed = judge::secret_seed_or(21);
	check_estimate(estimate_mixture(scene, point, normal, 100000, seed),
	               estimate(Pathtracer(scene, Render_Settings{}), Strategy::mixture, point, normal, 100000,
	                        reference_seed(seed)),
	               expected, "sample_incoming's mixture under a sphere light (handout §6.2)");

	// The probe: a black sphere half way to the light, off its axis, hides part of it.
	Scene probe;
	add_object(probe, Sphere{float(radius)}, add_material(probe, emitter(Spectrum{1.0f}), "light"),
	           glm::translate(Mat4{1.0f}, Vec3{0.0f, float(distance), 0.0f}));
	add_object(probe, Sphere{float(0.25 * radius)}, add_material(probe, diffuse_material(Spectrum{0.0f}), "blocker"),
	           glm::translate(Mat4{1.0f}, Vec3{float(0.15 * radius), float(0.5 * distance), 0.0f}));
	probe.commit();
	uint64_t probe_seed = judge::secret_seed_or(22);
	check_probe(estimate_mixture(probe, point, normal, 100000, probe_seed),
	            estimate(Pathtracer(probe, Render_Settings{}), Strategy::mixture, point, normal, 100000,
	                     reference_seed(probe_seed)),
	            "the probe, this sphere light with a black sphere hiding part of it");
}

TEST_CASE("under a small light, the mixture has a lower variance than BSDF sampling alone", "[id:t6.lighting.lower-variance][statistical:1][task6][uses:sample_incoming]") {
	// Square of half-side 0.1 at height 1: BSDF sampling finds it 1.3% of the time, light sampling
	// every time. One-sided z-test of var(BSDF) - var(mixture) > 0, with the sampling variance of
	// a sample variance, (m4 - s^4) / n.
	Scene scene = ceiling_light_scene(0.1f, 1.0f);
	Pathtracer pt(scene, Render_Settings{});
	Trace point = surface_point(Vec3{0.0f}, Vec3{0.0f, 1.0f, 0.0f});
	Vec3 out_dir{0.0f, 1.0f, 0.0f};
	Sample_Moments bsdf = moments(estimate(pt, Strategy::bsdf, point, out_dir, 100000, judge::secret_seed_or(31)));
	Sample_Moments mixture =
		moments(estimate_mixture(scene, point, out_dir, 100000, judge::secret_seed_or(32)));
	double z = (bsdf.variance - mixture.variance) /
	           std::sqrt(bsdf.variance_of_variance() + mixture.variance_of_variance());
	double critical = stats::normal_quantile(1.0 - judge::significance()); // one-sided
	INFO("per-sample variance: BSDF sampling " << bsdf.variance << ", sample_incoming " << mixture.variance
	                                           << " (z = " << z << ", must exceed " << critical
	                                           << "). Light sampling is what makes small lights cheap "
	                                           << "(handout §6.1)");
	CHECK(z > critical);
}

TEST_CASE("a diffuse floor under a square light renders as rho E / pi (max_depth 1)", "[id:t6.lighting.floor][statistical:6][estimate][task6][uses:sample_incoming]") {
	// Lambert's formula for a parallel square of half-side a at height h, under its centre:
	// a/h = 0.5 -> E = 0.752275 L, a/h = 1 -> E = 1.740840 L (light_closed_forms.h). With a grading
	// seed, two squares of half-side 0.3 to 1.2 at height 0.7 to 1.5, of radiance 0.5 to 3.
	REQUIRE(closed_form::centred_square_irradiance(0.5, 1.0, 1.0) == Approx(0.752275).epsilon(1e-6));
	REQUIRE(closed_form::centred_square_irradiance(1.0, 1.0, 1.0) == Approx(1.740840).epsilon(1e-6));
	struct Case {
		float half_side, height, radiance;
		uint64_t seed;
	};
	std::vector<Case> cases{Case{0.5f, 1.0f, 2.0f, 41}, Case{1.0f, 1.0f, 1.0f, 42}};
	if (std::optional<RNG> secret = judge::secret_inputs()) {
		RNG& rng = *secret;
		for (Case& c : cases) {
			c = Case{0.3f + 0.9f * rng.unit(), 0.7f + 0.8f * rng.unit(), 0.5f + 2.5f * rng.unit(),
			         uint64_t(rng.integer()) << 32 | rng.integer()};
		}
	}
	for (Case c : cases) {
		Scene scene = lit_floor(RHO, c.half_side, c.height, Spectrum{c.radiance}, Vec3{0.6f, 0.4f, 0.5f});
		scene.commit();
		double e = closed_form::centred_square_irradiance(c.half_side, c.height, c.radiance);
		check_estimate(channel_averages(render_samples(scene, one_pixel(c.seed), 50000)),
		               channel_averages(reference_render_samples(scene, one_pixel(c.seed), 50000)), RHO * e / M_PI,
		               "pixel under a square light with a/h = " + std::to_string(c.half_side / c.height) +
		                   ", L = " + std::to_string(c.radiance) + " (the renderer with your sample_incoming, "
		                   "handout §6.2)");
	}

	// The probe: the first floor with a blocker three quarters of the way up (above the camera, whose
	// eye is at height 0.4), away from the camera's side, hiding about half of the light.
	const Case& c = cases[0];
	Scene probe = lit_floor(RHO, c.half_side, c.height, Spectrum{c.radiance}, Vec3{0.6f, 0.4f, 0.5f});
	add_blocker(probe, Vec3{-0.4f * c.half_side, 0.75f * c.height, 0.0f}, 0.3f * c.half_side);
	probe.commit();
	Render_Settings settings = one_pixel(c.seed + 1);
	check_probe(channel_averages(render_samples(probe, settings, 50000)),
	            channel_averages(reference_render_samples(probe, settings, 50000)),
	            "the probe, this floor with a blocker hiding part of the light (the renderer with your sample_incoming)");
}

TEST_CASE("a light hidden behind a blocker gives exactly 0", "[id:t6.lighting.blocked][task6][uses:sample_incoming]") {
	// A black square between the floor and the light covers the light as seen from the floor's
	// centre; the camera looks at that centre from the side, under the blocker. No direction can
	// bring light, so every sample is exactly 0, never NaN.
	Scene scene = lit_floor(RHO, 0.5f, 1.0f, Spectrum{1.0f}, Vec3{2.0f, 0.1f, 0.0f});
	add_object(scene, ceiling_square(0.6f, 0.5f), add_material(scene, diffuse_material(Spectrum{0.0f}), "blocker"));
	scene.commit();
	std::vector<Spectrum> values = render_samples(scene, one_pixel(judge::secret_seed_or(51)), 20000);
	for (size_t i = 0; i < values.size(); i++) {
		Spectrum v = values[i];
		INFO("sample " << i << " of an occluded light: (" << v.r << ", " << v.g << ", " << v.b
		               << "); light must arrive only along rays that reach it (handout §6.2)");
		REQUIRE(v == Spectrum{0.0f});
	}
}

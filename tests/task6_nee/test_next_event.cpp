// Grader of task 6's optional extension, part 2: Pathtracer::estimate_direct and the NEE integrator
// built on it (handout §6.5). A shadow ray that is blocked gives exactly 0; the light-sampled share
// is what MIS with the power heuristic gives it; together with the BSDF-sampled share (weighted by
// the student's power_heuristic) it estimates Lambert's closed form; renders match closed forms and
// the stored reference image; and next-event estimation is less noisy than BSDF sampling. The
// student's functions answer in one request per estimate (student_calls.h); the rest is the grader's.
//
// Every z-test takes its standard error from the REFERENCE's estimator (the judge's own samples of
// the reference's estimate_direct, power_heuristic and NEE integrator, as many as the student's
// with another seed), never from the student's samples, and the student's samples may not be
// noisier than the reference's (the sign test on the variances of 50 batches of each,
// paired_noise.h: exact for any law of the samples). As many samples are enough: the reference's
// variance is off by sqrt((κ - 1) / n) relative, κ the samples' kurtosis (the NEE floors' 2.4 and
// 2.8, measured over 5e4 samples), about 1 % for n >= 5e4, so the standard error by half that.
#include "direct_lighting_estimators.h"
#include "estimator.h"
#include "frame.h"
#include "judge.h"
#include "light_closed_forms.h"
#include "light_scenes.h"
#include "nee_integrator.h"
#include "statistics.h"
#include "student_calls.h"
#include "student_renders.h"

#include "lab_catch2.h"
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace {

const float RHO = 0.5f; // albedo of every receiver
const BSDF GREY{BSDF_Lambertian{Spectrum{RHO}}};

// A tilted, off-centre receiver under a square light of half-side 0.5 at height 1 (as task 6's
// grader): local and world directions differ in every component.
const Vec3 POINT{0.2f, 0.0f, -0.1f};
const Vec3 NORMAL = glm::normalize(Vec3{0.25f, 1.0f, -0.15f});
const Vec3 OUT_DIR = glm::normalize(Vec3{-0.3f, 1.0f, 0.4f});

Render_Settings seeded_settings(uint64_t seed = 0) {
	Render_Settings settings;
	settings.seed = seed;
	return settings;
}

double channel_average(Spectrum s) {
	return (double(s.r) + double(s.g) + double(s.b)) / 3.0;
}

// The grader's own light-sampled share of next-event estimation: one light sample, the shadow ray,
// and the power heuristic, computed here in double precision.
double light_share(const Pathtracer& pt, RNG& rng, const Trace& point, Vec3 out_dir) {
	Light_Sample light = pt.sample_light(rng, point.position);
	if (!(light.pdf > 0.0f)) return 0.0;
	Frame frame = Frame::from_normal(point.normal);
	Vec3 out_local = frame.to_local(out_dir), in_local = frame.to_local(light.direction);
	Spectrum f = GREY.evaluate(out_local, in_local);
	Ray shadow(point.position, light.direction, Vec2{0.0f, Light_Sample::SHADOW_RAY_END * light.distance});
	if (f == Spectrum{0.0f} || pt.scene.occluded(shadow)) return 0.0;
	double p_light = light.pdf, p_bsdf = GREY.pdf(out_local, in_local);
	double weight = p_light * p_light / (p_light * p_light + p_bsdf * p_bsdf);
	return channel_average(f * light.radiance) * std::abs(double(in_local.y)) * weight / p_light;
}

// Whose power_heuristic weighs the BSDF-sampled share.
enum class Weights { student, reference };

// n samples of the BSDF-sampled share: emission found along a BSDF sample, weighted by the
// student's power_heuristic (one request for all n) or the reference's, against the light density
// of what the ray found.
std::vector<double> bsdf_share(const Pathtracer& pt, const Trace& point, Vec3 out_dir, size_t n, uint64_t seed,
                               Weights whose = Weights::student) {
	std::vector<double> values(n);
	std::vector<Vec2> densities(n); // (BSDF pdf, light pdf) of each sample
	RNG rng(seed);
	Frame frame = Frame::from_normal(point.normal);
	Vec3 out_local = frame.to_local(out_dir);
	for (size_t i = 0; i < n; i++) {
		Scatter s = GREY.scatter(rng, out_local);
		float pdf = GREY.pdf(out_local, s.direction);
		Ray ray(point.position, frame.to_world(s.direction));
		Trace hit = pt.scene.hit(ray);
		Spectrum arriving = hit.hit ? pt.scene.materials[hit.material].emitted(Vec3{0.0f, -glm::dot(ray.dir, hit.normal), 0.0f})
		                            : pt.scene.environment_radiance(ray.dir);
		values[i] = pdf > 0.0f ? channel_average(s.attenuation * arriving) * std::abs(s.direction.y) / pdf : 0.0;
		densities[i] = Vec2{pdf, light_pdf(pt, ray, hit)};
	}
	std::vector<float> weights(n);
	if (whose == Weights::student) weights = student_power_heuristic(densities);
	else for (size_t i = 0; i < n; i++) weights[i] = power_heuristic(densities[i].x, densities[i].y);
	for (size_t i = 0; i < n; i++) values[i] *= weights[i];
	return values;
}

// The reference's samples: another stream than the student's.
uint64_t reference_seed(uint64_t seed) {
	return seed ^ 0xa5a5a5a5a5a5a5a5ull;
}

// n values of the reference's estimate_direct at `point`, from one generator (as student_direct_light).
std::vector<double> reference_direct_light(const Pathtracer& pt, const Trace& point, Vec3 out_dir, size_t n,
                                           uint64_t seed) {
	RNG rng(reference_seed(seed));
	std::vector<double> values(n);
	for (double& v : values) v = channel_average(pt.estimate_direct(rng, point, GREY, out_dir));
	return values;
}

// n samples of pixel (0, 0) by the reference's NEE integrator (as student_pixel_samples).
std::vector<double> reference_pixel_samples(const Scene& scene, Render_Settings settings, size_t n) {
	settings.seed = reference_seed(settings.seed);
	Pathtracer pt(scene, settings, View::path, Estimator_Choice{"nee"});
	std::vector<double> values(n);
	for (size_t i = 0; i < n; i++) {
		RNG rng = RNG::for_sample(settings.seed, 0, i);
		values[i] = channel_average(pt.trace_pixel(0, 0, rng));
	}
	return values;
}

// The student's noise against the reference's (one check); whether it passed.
bool check_noise(const std::vector<double>& student, const std::vector<double>& reference, const std::string& what) {
	Paired_Noise noise = compare_noise(student, reference, judge::significance());
	INFO(what << ": too noisy: " << describe(noise, "batch") << ". Both shares weighted by the power "
	          "heuristic keep a light sample's weight bounded: f L |cos| w / pdf with w = power_heuristic(light pdf, "
	          "BSDF pdf) (handout §6.5)");
	CHECK(noise.pass);
	return noise.pass;
}

std::vector<double> sum(const std::vector<double>& a, const std::vector<double>& b) {
	std::vector<double> s(a.size());
	for (size_t i = 0; i < a.size(); i++) s[i] = a[i] + b[i];
	return s;
}

// The student's estimate against the closed form with the reference's standard error, and its noise
// against the reference's (two checks).
void check_closed_form(const std::vector<double>& student_samples, const std::vector<double>& reference_samples,
                       double expected, const std::string& what) {
	bool quiet = check_noise(student_samples, reference_samples, what); // first: noise makes the mean stray
	Sample_Moments student = moments(student_samples), reference = moments(reference_samples);
	double error = standard_error(reference, student.n);
	double z = (student.mean - expected) / error, critical = judge::z_critical();
	INFO(what << ": estimated " << student.mean << " +- " << error << " (" << student.n
	          << " samples; the standard error of the reference's estimator), closed form " << expected << ", z = "
	          << z << " (critical " << critical << ")"
	          << (quiet ? "" : "; your estimator is noisier than the reference's (above), so its mean strays further"));
	CHECK(std::abs(z) <= critical);
}

// A 1 x 1 film that sees only the floor of lit_floor (light_scenes.h).
Render_Settings one_pixel(uint64_t seed) {
	Render_Settings settings = seeded_settings(seed);
	settings.width = settings.height = 1;
	settings.max_depth = 1; // direct light only
	return settings;
}

} // namespace

TEST_CASE("estimate_direct gives exactly 0 when the shadow ray is blocked", "[id:t6nee.direct.blocked][task6_nee][fn:estimate_direct]") {
	// A black square between the point and the light covers the light as seen from the point.
	Scene scene = ceiling_light_scene(0.5f, 1.0f);
	scene.objects = std::move(scene.bvh.primitives); // reopen the committed scene
	add_object(scene, ceiling_square(0.8f, 0.5f), add_material(scene, diffuse_material(Spectrum{0.0f}), "blocker"));
	scene.commit();
	Pathtracer pt(scene, seeded_settings());
	std::vector<double> values = student_direct_light(pt.scene, pt.settings, surface_point(Vec3{0.0f}, Vec3{0.0f, 1.0f, 0.0f}), GREY,
	                                                  Vec3{0.0f, 1.0f, 0.0f}, 20000, 1);
	size_t nonzero = size_t(std::count_if(values.begin(), values.end(), [](double v) { return v != 0.0; }));
	INFO(nonzero << " of 20000 light samples behind a blocker returned light: cast the shadow ray with "
	                "scene.occluded from hit.position towards the light, up to SHADOW_RAY_END * distance (handout "
	                "§6.5)");
	CHECK(nonzero == 0);
}

TEST_CASE("estimate_direct gives exactly 0 for a light behind the surface", "[id:t6nee.direct.light-behind][task6_nee][fn:estimate_direct]") {
	Scene scene = ceiling_light_scene(0.5f, 1.0f);
	Pathtracer pt(scene, seeded_settings());
	Vec3 down{0.0f, -1.0f, 0.0f}; // a surface facing away from the light, seen from below
	std::vector<double> values = student_direct_light(pt.scene, pt.settings, surface_point(Vec3{0.0f}, down), GREY, down, 20000, 2);
	size_t bad = size_t(std::count_if(values.begin(), values.end(), [](double v) { return v != 0.0; }));
	INFO(bad << " of 20000 samples of a light behind the surface were not 0: the BSDF is 0 there (handout §6.5)");
	CHECK(bad == 0);
}

TEST_CASE("estimate_direct's mean is the light-sampled share the power heuristic gives it",
          "[id:t6nee.direct.mean][statistical:2][estimate][task6_nee][fn:estimate_direct]") {
	// Two-sample z-test against the grader's own light samples, weighted by p_l^2 / (p_l^2 + p_b^2).
	Scene scene = ceiling_light_scene(0.5f, 1.0f);
	Pathtracer pt(scene, seeded_settings());
	Trace point = surface_point(POINT, NORMAL);
	std::vector<double> student_samples = student_direct_light(pt.scene, pt.settings, point, GREY, OUT_DIR, 100000, 11);
	std::vector<double> own(100000);
	RNG rng(12);
	for (double& v : own) v = light_share(pt, rng, point, OUT_DIR);
	Sample_Moments student = moments(student_samples), grader = moments(own);
	// Both means estimate the same value if the student's is right; the difference's standard error
	// is the grader's per-sample deviation over both sample counts (never the student's own).
	double error = std::sqrt(grader.variance * (1.0 / double(student.n) + 1.0 / double(grader.n)));
	double z = (student.mean - grader.mean) / error, critical = judge::z_critical();
	{
		INFO("estimate_direct averaged " << student.mean << "; light samples weighted by the power heuristic average "
		                                 << grader.mean << ", difference +- " << error << ", z = " << z
		                                 << " (critical " << critical
		                                 << "). Return f * L * |cos| * w / pdf with w = power_heuristic(light pdf, "
		                                    "BSDF pdf) (handout §6.5)");
		CHECK(std::abs(z) <= critical);
	}
	check_noise(student_samples, own, "estimate_direct at a tilted receiver under a square light");
}

TEST_CASE("light-sampled and BSDF-sampled shares add up to Lambert's formula",
          "[id:t6nee.direct.lambert][statistical:4][estimate][task6_nee][uses:estimate_direct][uses:power_heuristic]") {
	SECTION("a square light over a tilted receiver") {
		Scene scene = ceiling_light_scene(0.5f, 1.0f);
		Pathtracer pt(scene, seeded_settings());
		Trace point = surface_point(POINT, NORMAL);
		double e = closed_form::polygon_irradiance(ceiling_square_corners(0.5f, 1.0f), glm::dvec3(POINT),
		                                           glm::dvec3(NORMAL), 1.0);
		std::vector<double> both = sum(student_direct_light(pt.scene, pt.settings, point, GREY, OUT_DIR, 100000, 21),
		                               bsdf_share(pt, point, OUT_DIR, 100000, 22));
		std::vector<double> reference = sum(reference_direct_light(pt, point, OUT_DIR, 100000, 21),
		                                    bsdf_share(pt, point, OUT_DIR, 100000, reference_seed(22), Weights::reference));
		check_closed_form(both, reference, RHO * e / M_PI,
		                  "estimate_direct + BSDF samples weighted by power_heuristic, square light: each share must "
		                  "be weighted by the heuristic of its own density against the other's (handout §6.5)");
	}
	SECTION("a sphere light 30 degrees off the normal") {
		Scene scene;
		add_object(scene, Sphere{0.5f}, add_material(scene, emitter(Spectrum{1.0f}), "light"),
		           glm::translate(Mat4{1.0f}, Vec3{0.0f, 2.0f, 0.0f}));
		scene.commit();
		Pathtracer pt(scene, seeded_settings());
		Vec3 normal{std::sin(PI_F / 6.0f), std::cos(PI_F / 6.0f), 0.0f};
		Trace point = surface_point(Vec3{0.0f}, normal);
		double expected = RHO * closed_form::sphere_irradiance(0.5, 2.0, std::cos(M_PI / 6.0), 1.0) / M_PI;
		std::vector<double> both = sum(student_direct_light(pt.scene, pt.settings, point, GREY, normal, 100000, 23),
		                               bsdf_share(pt, point, normal, 100000, 24));
		std::vector<double> reference = sum(reference_direct_light(pt, point, normal, 100000, 23),
		                                    bsdf_share(pt, point, normal, 100000, reference_seed(24), Weights::reference));
		check_closed_form(both, reference, expected,
		                  "estimate_direct + BSDF samples weighted by power_heuristic, sphere light (half of its "
		                  "points face away: their shadow rays are blocked by the sphere itself; handout §6.5)");
	}
}

TEST_CASE("the NEE integrator renders a floor under a square light as rho E / pi (max_depth 1)",
          "[id:t6nee.integrator.floor][statistical:4][estimate][task6_nee][uses:estimate_direct][uses:power_heuristic]") {
	struct Case {
		float half_side, height, radiance;
		uint64_t seed;
	};
	for (Case c : {Case{0.5f, 1.0f, 2.0f, 41}, Case{1.0f, 1.0f, 1.0f, 42}}) {
		Scene scene = lit_floor(RHO, c.half_side, c.height, Spectrum{c.radiance}, Vec3{0.6f, 0.4f, 0.5f});
		scene.commit();
		Pathtracer pt(scene, one_pixel(c.seed));
		double e = closed_form::centred_square_irradiance(c.half_side, c.height, c.radiance);
		check_closed_form(student_pixel_samples(pt.scene, pt.settings, 50000),
		                  reference_pixel_samples(pt.scene, pt.settings, 50000), RHO * e / M_PI,
		                  "pixel under a square light with a/h = " + std::to_string(c.half_side / c.height) +
		                      " by --integrator nee with your estimate_direct and power_heuristic (handout §6.5)");
	}
}

TEST_CASE("under a small light, next-event estimation is less noisy than BSDF sampling",
          "[id:t6nee.integrator.lower-variance][statistical:1][task6_nee][uses:estimate_direct][uses:power_heuristic]") {
	// Square of half-side 0.1 at height 1 over a point facing it: one-sided z-test of var(BSDF) -
	// var(NEE) > 0, with the sampling variance of a sample variance, (m4 - s^4) / n.
	Scene scene = ceiling_light_scene(0.1f, 1.0f);
	Pathtracer pt(scene, seeded_settings());
	Trace point = surface_point(Vec3{0.0f}, Vec3{0.0f, 1.0f, 0.0f});
	Vec3 up{0.0f, 1.0f, 0.0f};
	Sample_Moments nee = moments(sum(student_direct_light(pt.scene, pt.settings, point, GREY, up, 100000, 31),
	                                 bsdf_share(pt, point, up, 100000, 32)));
	std::vector<double> bsdf(100000);
	RNG rng(33);
	for (double& v : bsdf) v = reflected_radiance_sample(scene, point, draw(pt, Strategy::bsdf, rng, point, GREY, up));
	Sample_Moments alone = moments(bsdf);
	double z = (alone.variance - nee.variance) / std::sqrt(alone.variance_of_variance() + nee.variance_of_variance());
	double critical = stats::normal_quantile(1.0 - judge::significance()); // one-sided
	INFO("per-sample variance: BSDF sampling " << alone.variance << ", next-event estimation " << nee.variance
	                                           << " (z = " << z << ", must exceed " << critical
	                                           << "): light samples are what make small lights cheap (handout §6.5)");
	CHECK(z > critical);
}

TEST_CASE("the NEE integrator renders cornell_small_light like its reference image",
          "[id:t6nee.image.cornell-small-light][estimate][task6_nee][image][statistical:2][uses:estimate_direct][uses:power_heuristic]") {
	Image_Test test;
	test.name = "cornell_small_light";
	test.hint = "--integrator nee with your estimate_direct and power_heuristic: each share must be weighted by the "
	            "power heuristic of its own density against the other's (handout §6.5).";
	test.if_failed = {{"power_heuristic", "the weights of the two strategies (handout §6.5)."},
	                  {"estimate_direct", "the light-sampled share and its shadow ray (handout §6.5)."}};
	test.if_noisy = "Both shares weighted by the power heuristic keep a light sample's weight bounded: f L |cos| w / pdf "
	                "with w = power_heuristic(light pdf, BSDF pdf) (handout §6.5).";
	test.integrator = "nee";
	check_renders_like_reference(test);
}

// Task 4, handout §4.1: the Lambertian BSDF (BSDF_Lambertian in framework/api/material.h).
// Local frame: the normal is +y, out_dir and in_dir both point away from the surface. The BSDF is
// two-sided: it reflects on whichever side out_dir lies.
//
// The student's scatter, evaluate and pdf run in the subject (grading/judge/protocol.h); expected
// values are the handout's formulas in double (albedo / pi, |cos theta_in| / pi), never the
// reference's float answers. With a grading seed the albedo, the directions and the
// generators' seeds are drawn from it.
#include "judge.h"
#include "material.h"
#include "statistics.h"
#include "student_overlapped.h"

#include "lab_catch2.h"

#include <array>
#include <cmath>
#include <optional>
#include <vector>

using protocol::BSDF_Evaluate;
using protocol::BSDF_Pdf;
using protocol::BSDF_Scatter;
using protocol::Direction_Pair;

namespace {

constexpr double PI = 3.14159265358979323846;

// The unit direction with cos(theta) = y uniform in [y_lo, y_hi] and a random azimuth.
Vec3 random_direction(RNG& rng, float y_lo, float y_hi) {
	float y = y_lo + (y_hi - y_lo) * rng.unit(), phi = 2.0f * float(PI) * rng.unit();
	float r = std::sqrt(std::max(0.0f, 1.0f - y * y));
	return Vec3{r * std::cos(phi), y, r * std::sin(phi)};
}

// The test's inputs: the public ones, or with a grading seed drawn from the same ranges.
struct Inputs {
	Spectrum albedo{0.9f, 0.5f, 0.2f};
	// out_dirs above and below the surface, at the normal, oblique and near-grazing.
	std::array<Vec3, 5> out_dirs{
		Vec3{0.0f, 1.0f, 0.0f},
		glm::normalize(Vec3{0.3f, 0.8f, -0.5f}),
		glm::normalize(Vec3{0.9999f, 0.01f, 0.0f}),
		Vec3{0.0f, -1.0f, 0.0f},
		glm::normalize(Vec3{-0.4f, -0.3f, 0.6f}),
	};
	// in_dirs above the surface, for evaluate.
	std::array<Vec3, 3> in_dirs{Vec3{0.0f, 1.0f, 0.0f}, glm::normalize(Vec3{0.7f, 0.2f, 0.1f}),
	                            glm::normalize(Vec3{-0.1f, 0.05f, -0.9f})};
	uint64_t seed = 0; // for the generators; 0 means the public seeds
};

Inputs inputs() {
	Inputs in;
	std::optional<RNG> secret = judge::secret_inputs();
	if (!secret) return in;
	RNG& rng = *secret;
	in.albedo = Spectrum{0.05f + 0.95f * rng.unit(), 0.05f + 0.95f * rng.unit(), 0.05f + 0.95f * rng.unit()};
	in.out_dirs = {random_direction(rng, 0.9f, 1.0f), random_direction(rng, 0.2f, 0.9f),
	               random_direction(rng, 0.002f, 0.02f), random_direction(rng, -1.0f, -0.9f),
	               random_direction(rng, -0.9f, -0.2f)};
	for (Vec3& d : in.in_dirs) d = random_direction(rng, 0.02f, 1.0f);
	in.seed = judge::seed_or_public(secret, 0);
	return in;
}

bool close(float a, float b, float relative) {
	return std::abs(a - b) <= relative * std::max(std::abs(a), std::abs(b));
}

std::string side(Vec3 v) {
	return v.y > 0.0f ? "above the surface (y > 0)" : "below the surface (y < 0)";
}

BSDF lambertian(Spectrum albedo) {
	return BSDF(BSDF_Lambertian{albedo});
}

} // namespace

TEST_CASE("Lambertian evaluate: albedo / pi, without the cosine, on out_dir's side; 0 across the surface", "[id:t4.lambertian.evaluate][fn:Lambertian::evaluate]") {
	const Inputs in = inputs();
	BSDF_Evaluate request{lambertian(in.albedo), {}};
	for (Vec3 out : in.out_dirs) {
		for (Vec3 dir : in.in_dirs) {
			if (out.y < 0.0f) dir.y = -dir.y; // same side as out
			request.pairs.push_back({out, dir});
			request.pairs.push_back({out, Vec3{dir.x, -dir.y, dir.z}}); // across the surface
		}
	}
	std::vector<Spectrum> values = judge::ask(request);
	for (size_t i = 0; i < values.size(); i += 2) {
		Vec3 out = request.pairs[i].out_dir, dir = request.pairs[i].in_dir;
		CAPTURE(out.x, out.y, out.z, dir.x, dir.y, dir.z);
		// albedo / pi, exactly (in double), never the reference's float answer.
		Spectrum f = values[i], expected = Spectrum(glm::dvec3(in.albedo) / PI);
		bool is_albedo = true, has_cosine = true;
		for (int c = 0; c < 3; c++) {
			is_albedo = is_albedo && close(f[c], in.albedo[c], 1e-5f);
			has_cosine = has_cosine && close(f[c], expected[c] * std::abs(dir.y), 1e-5f) && std::abs(dir.y) < 0.99f;
		}
		INFO("evaluate(out, in) = (" << f.r << ", " << f.g << ", " << f.b << "), expected albedo / pi = ("
		     << expected.r << ", " << expected.g << ", " << expected.b << ") for out " << side(out)
		     << " and in on the same side. "
		     << (is_albedo    ? "That is the albedo itself: divide it by pi, so that the cosine-weighted integral of f "
		                        "over the hemisphere is the albedo (handout §4.1)"
		         : has_cosine ? "That is albedo / pi times cos(theta_in): evaluate is f alone, the estimator "
		                        "multiplies by the cosine (handout §4.1)"
		                      : "evaluate is f alone: no cosine (handout §4.1)"));
		for (int c = 0; c < 3; c++) CHECK(close(f[c], expected[c], 1e-6f));

		INFO("in_dir on the other side of the surface than out_dir: light cannot pass through a diffuse "
		     "surface, so evaluate must be 0");
		CHECK(values[i + 1] == Spectrum{0.0f});
	}
}

TEST_CASE("Lambertian pdf: |cos theta_in| / pi on out_dir's side, 0 across, and it integrates to 1", "[id:t4.lambertian.pdf][fn:Lambertian::pdf]") {
	const Inputs in = inputs();
	// Midpoint rule over cells equal in (cos theta, phi); it is exact for a density linear in
	// cos theta on each cell (no cell straddles cos theta = 0).
	const int n_cos = 200, n_phi = 64;
	const double cell_area = (2.0 / n_cos) * (2.0 * PI / n_phi);
	BSDF_Pdf request{lambertian(in.albedo), {}};
	for (Vec3 out : in.out_dirs) {
		for (int i = 0; i < n_cos; i++) {
			double c = -1.0 + (i + 0.5) * 2.0 / n_cos;
			double s = std::sqrt(1.0 - c * c);
			for (int j = 0; j < n_phi; j++) {
				double phi = (j + 0.5) * 2.0 * PI / n_phi;
				request.pairs.push_back({out, Vec3{float(s * std::cos(phi)), float(c), float(s * std::sin(phi))}});
			}
		}
	}
	std::vector<float> pdfs = judge::ask(request);
	const size_t per_out = size_t(n_cos) * n_phi;
	for (size_t k = 0; k < in.out_dirs.size(); k++) {
		Vec3 out = in.out_dirs[k];
		CAPTURE(out.x, out.y, out.z);
		double integral = 0.0;
		bool pointwise_ok = true;
		for (size_t n = k * per_out; n < (k + 1) * per_out; n++) {
			Vec3 dir = request.pairs[n].in_dir;
			float p = pdfs[n];
			// |cos theta_in| / pi on out_dir's side, 0 across (no cell touches the surface), in double.
			double expected = double(out.y) * double(dir.y) > 0.0 ? std::abs(double(dir.y)) / PI : 0.0;
			if (pointwise_ok && !(std::abs(p - expected) <= 1e-6 * std::max(1.0, expected))) {
				pointwise_ok = false;
				INFO("pdf(out, in) with out " << side(out) << ", in = (" << dir.x << ", " << dir.y << ", " << dir.z
				     << ") is " << p << ", expected " << expected
				     << (expected == 0.0 ? " (in_dir is across the surface: scatter never goes there)"
				                         : " = |in.y| / pi (cosine-weighted hemisphere on out_dir's side)"));
				CHECK(p == Approx(expected));
			}
			integral += double(p) * cell_area;
		}
		INFO("the integral of pdf(out, in) over all in_dir (out " << side(out) << ") is " << integral
		     << ", but a probability density over directions must integrate to 1 (handout §4.1)");
		CHECK(std::abs(integral - 1.0) < 1e-4);
	}
}

TEST_CASE("Lambertian scatter: unit in_dir on out_dir's side, attenuation = evaluate, f |cos| / pdf = albedo", "[id:t4.lambertian.scatter][fn:Lambertian::scatter][uses:Lambertian::evaluate][uses:Lambertian::pdf]") {
	const Inputs in = inputs();
	const Spectrum albedo = in.albedo;
	constexpr size_t SAMPLES = 10000; // per out_dir
	BSDF_Scatter request{lambertian(albedo), {}, RNG_State::of(in.seed ? RNG(in.seed) : RNG(4, 1))};
	for (Vec3 out : in.out_dirs) request.out_dirs.insert(request.out_dirs.end(), SAMPLES, out);
	std::vector<Scatter> samples = judge::ask(request);
	// The student's evaluate and pdf at the sampled directions.
	BSDF_Evaluate evaluate{request.bsdf, {}};
	for (size_t n = 0; n < samples.size(); n++) evaluate.pairs.push_back({request.out_dirs[n], samples[n].direction});
	std::vector<Spectrum> fs = judge::ask(evaluate);
	std::vector<float> pdfs = judge::ask(BSDF_Pdf{request.bsdf, evaluate.pairs});

	for (size_t k = 0; k < in.out_dirs.size(); k++) {
		Vec3 out = in.out_dirs[k];
		CAPTURE(out.x, out.y, out.z);
		for (size_t i = 0; i < SAMPLES; i++) {
			const size_t n = k * SAMPLES + i;
			const Scatter& s = samples[n];
			Vec3 dir = s.direction;
			Spectrum f = fs[n];
			float p = pdfs[n];
			// With cosine sampling the weight is (albedo / pi) |cos| / (|cos| / pi) = albedo: the
			// cosines cancel exactly, so only float rounding remains.
			Spectrum weight = f * std::abs(dir.y) / p;
			bool unit = std::abs(glm::length(dir) - 1.0f) < 1e-5f;
			bool same_side = dir.y * out.y > 0.0f;
			bool attenuation_is_f = true, weight_is_albedo = true;
			for (int c = 0; c < 3; c++) {
				attenuation_is_f = attenuation_is_f && close(s.attenuation[c], f[c], 1e-6f);
				weight_is_albedo = weight_is_albedo && close(weight[c], albedo[c], 1e-5f);
			}
			if (unit && same_side && attenuation_is_f && weight_is_albedo) continue;
			// A direction in the surface (y = +-0), which a cosine sampler reaches only by rounding (a disk
			// point rounded onto the rim), has density 0 and carries no weight (shade ends the path,
			// handout §4.2): not wrong. The chi-square test counts it on out_dir's side.
			if (unit && dir.y == 0.0f && attenuation_is_f) continue;

			INFO("sample " << i << ": in_dir = (" << dir.x << ", " << dir.y << ", " << dir.z << "), attenuation = ("
			     << s.attenuation.r << ", " << s.attenuation.g << ", " << s.attenuation.b << ")");
			{
				INFO("scatter must return a unit-length direction");
				CHECK(unit);
			}
			{
				INFO("in_dir must lie on the same side as out_dir (" << side(out)
				     << "): the BSDF is two-sided, flip the hemisphere sample when out_dir.y < 0 (handout §4.1)");
				CHECK(same_side);
			}
			{
				INFO("Scatter::attenuation must be evaluate(out_dir, in_dir) = (" << f.r << ", " << f.g << ", " << f.b
				     << "): for a continuous BSDF it is f, the estimator multiplies by |cos| / pdf");
				CHECK(attenuation_is_f);
			}
			{
				INFO("evaluate * |cos| / pdf = (" << weight.r << ", " << weight.g << ", " << weight.b
				     << ") must equal the albedo (" << albedo.r << ", " << albedo.g << ", " << albedo.b
				     << ") for every cosine-weighted sample (pdf = " << p << ")");
				CHECK(weight_is_albedo);
			}
			break; // one sample explained is enough
		}
	}
}

TEST_CASE("Lambertian scatter: directions follow the cosine density |cos theta| / pi (chi-square), on both sides", "[id:t4.lambertian.scatter-chi2][statistical:5][fn:Lambertian::scatter][uses:Lambertian::evaluate][uses:Lambertian::pdf]") {
	// Cells of equal solid angle: n_cos slices of cos theta in [-1, 1] times n_phi slices of phi.
	// The probability of cell [c0, c1] x [phi0, phi1] on out_dir's side is
	// integral |c| / pi dc dphi = |c1^2 - c0^2| / 2 * (2 pi / n_phi) / pi = |c1^2 - c0^2| / n_phi; across
	// the surface it is 0 and any sample there fails the test.
	constexpr size_t n_cos = 40, n_phi = 80, samples = 1000000, chunks = 10;
	const Inputs in = inputs();
	for (size_t k = 0; k < in.out_dirs.size(); k++) {
		Vec3 out = in.out_dirs[k];
		CAPTURE(out.x, out.y, out.z);
		std::vector<double> observed(n_cos * n_phi, 0.0), expected(n_cos * n_phi, 0.0);
		for (size_t i = 0; i < n_cos; i++) {
			double c0 = -1.0 + 2.0 * double(i) / n_cos, c1 = -1.0 + 2.0 * double(i + 1) / n_cos;
			bool on_out_side = 0.5 * (c0 + c1) * out.y > 0.0;
			for (size_t j = 0; j < n_phi; j++) {
				expected[i * n_phi + j] = on_out_side ? samples * std::abs(c1 * c1 - c0 * c0) / n_phi : 0.0;
			}
		}
		// Asked for in chunks, each with a generator of its own, so that no request or answer is
		// larger than a few megabytes; one chunk is counted while the subject samples the next.
		size_t invalid = 0;
		auto chunk_request = [&](size_t chunk) {
			RNG rng(in.seed ? in.seed : 2024, k * chunks + chunk);
			return BSDF_Scatter{lambertian(in.albedo), std::vector<Vec3>(samples / chunks, out), RNG_State::of(rng)};
		};
		auto count = [&](size_t, const std::vector<Scatter>& scatters) {
			for (const Scatter& s : scatters) {
				Vec3 dir = s.direction;
				if (!is_finite(dir) || std::abs(glm::length(dir) - 1.0f) > 1e-4f) {
					invalid++;
					continue;
				}
				float phi = std::atan2(dir.z, dir.x);
				if (phi < 0.0f) phi += 2.0f * float(PI);
				size_t i = std::min(size_t((dir.y + 1.0f) * 0.5f * n_cos), n_cos - 1);
				// A direction in the surface (y = +-0) is on neither side: a cosine sampler reaches it only
				// by rounding (a disk point that rounds onto the rim, e.g. with the concentric map), and
				// its density there is 0. It borders out_dir's side: counted there, never as across.
				if (dir.y == 0.0f) i = out.y > 0.0f ? n_cos / 2 : n_cos / 2 - 1;
				size_t j = std::min(size_t(phi / (2.0f * float(PI)) * n_phi), n_phi - 1);
				observed[i * n_phi + j] += 1.0;
			}
		};
		ask_each_while_using_the_last(chunks, chunk_request, count);
		INFO(invalid << " of " << samples << " sampled directions were not finite unit vectors");
		REQUIRE(invalid == 0);
		stats::Chi2_Result r = stats::chi2_test(observed, expected);
		const double alpha = judge::significance(); // one chi-square test per out_dir
		INFO("chi-square " << r.statistic << " with " << r.dof << " degrees of freedom, p-value " << r.p_value
		     << " (reject below " << alpha << "); " << r.observed_in_impossible_cells
		     << " samples landed across the surface from out_dir (" << side(out) << ")");
		INFO("the sampled in_dir must be distributed like cos(theta) / pi on out_dir's side: e.g. Malley's method "
		     "(a uniform disk point lifted onto the hemisphere), handout §4.1");
		CHECK(r.observed_in_impossible_cells == 0.0);
		CHECK(r.p_value >= alpha);
		if (r.observed_in_impossible_cells != 0.0 || r.p_value < alpha) return; // one out_dir explained is enough
	}
}

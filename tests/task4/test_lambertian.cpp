// Task 4, handout §4.1: the Lambertian BSDF (BSDF_Lambertian in framework/material.h).
// Local frame: the normal is +y, out_dir and in_dir both point away from the surface. The BSDF is
// two-sided: it reflects on whichever side out_dir lies.
#include "material.h"
#include "statistics.h"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <vector>

namespace {

constexpr double PI = 3.14159265358979323846;
const Spectrum ALBEDO{0.9f, 0.5f, 0.2f};

// out_dirs above and below the surface, at the normal, oblique and near-grazing.
const std::array<Vec3, 5> OUT_DIRS{
	Vec3{0.0f, 1.0f, 0.0f},
	glm::normalize(Vec3{0.3f, 0.8f, -0.5f}),
	glm::normalize(Vec3{0.9999f, 0.01f, 0.0f}),
	Vec3{0.0f, -1.0f, 0.0f},
	glm::normalize(Vec3{-0.4f, -0.3f, 0.6f}),
};

bool close(float a, float b, float relative) {
	return std::abs(a - b) <= relative * std::max(std::abs(a), std::abs(b));
}

std::string side(Vec3 v) {
	return v.y > 0.0f ? "above the surface (y > 0)" : "below the surface (y < 0)";
}

} // namespace

TEST_CASE("Lambertian evaluate: albedo / pi, without the cosine, on out_dir's side; 0 across the surface") {
	BSDF_Lambertian bsdf{ALBEDO};
	const Spectrum expected = ALBEDO / float(PI);
	for (Vec3 out : OUT_DIRS) {
		for (Vec3 in : {Vec3{0.0f, 1.0f, 0.0f}, glm::normalize(Vec3{0.7f, 0.2f, 0.1f}),
		                glm::normalize(Vec3{-0.1f, 0.05f, -0.9f})}) {
			if (out.y < 0.0f) in.y = -in.y; // same side as out
			CAPTURE(out.x, out.y, out.z, in.x, in.y, in.z);
			Spectrum f = bsdf.evaluate(out, in);
			INFO("evaluate(out, in) = (" << f.r << ", " << f.g << ", " << f.b << "), expected albedo / pi = ("
			     << expected.r << ", " << expected.g << ", " << expected.b << ") for out " << side(out)
			     << " and in on the same side. evaluate is f alone: no cosine (handout §4.1)");
			for (int c = 0; c < 3; c++) CHECK(close(f[c], expected[c], 1e-6f));

			Vec3 across{in.x, -in.y, in.z};
			INFO("in_dir on the other side of the surface than out_dir: light cannot pass through a diffuse "
			     "surface, so evaluate must be 0");
			CHECK(bsdf.evaluate(out, across) == Spectrum{0.0f});
		}
	}
}

TEST_CASE("Lambertian pdf: |cos theta_in| / pi on out_dir's side, 0 across, and it integrates to 1") {
	BSDF_Lambertian bsdf{ALBEDO};
	for (Vec3 out : OUT_DIRS) {
		CAPTURE(out.x, out.y, out.z);
		// Midpoint rule over cells equal in (cos theta, phi); it is exact for a density linear in
		// cos theta on each cell (no cell straddles cos theta = 0).
		const int n_cos = 200, n_phi = 64;
		const double cell_area = (2.0 / n_cos) * (2.0 * PI / n_phi);
		double integral = 0.0;
		bool pointwise_ok = true;
		for (int i = 0; i < n_cos; i++) {
			double c = -1.0 + (i + 0.5) * 2.0 / n_cos;
			double s = std::sqrt(1.0 - c * c);
			for (int j = 0; j < n_phi; j++) {
				double phi = (j + 0.5) * 2.0 * PI / n_phi;
				Vec3 in{float(s * std::cos(phi)), float(c), float(s * std::sin(phi))};
				float p = bsdf.pdf(out, in);
				double expected = (c * out.y > 0.0) ? std::abs(c) / PI : 0.0;
				if (pointwise_ok && !(std::abs(p - expected) <= 1e-6 * std::max(1.0, expected))) {
					pointwise_ok = false;
					INFO("pdf(out, in) with out " << side(out) << ", in = (" << in.x << ", " << in.y << ", " << in.z
					     << ") is " << p << ", expected " << expected
					     << (expected == 0.0 ? " (in_dir is across the surface: scatter never goes there)"
					                         : " = |in.y| / pi (cosine-weighted hemisphere on out_dir's side)"));
					CHECK(p == Approx(expected));
				}
				integral += double(p) * cell_area;
			}
		}
		INFO("the integral of pdf(out, in) over all in_dir (out " << side(out) << ") is " << integral
		     << ", but a probability density over directions must integrate to 1 (handout §4.1)");
		CHECK(std::abs(integral - 1.0) < 1e-4);
	}
}

TEST_CASE("Lambertian scatter: unit in_dir on out_dir's side, attenuation = evaluate, f |cos| / pdf = albedo") {
	BSDF_Lambertian bsdf{ALBEDO};
	RNG rng(4, 1);
	for (Vec3 out : OUT_DIRS) {
		CAPTURE(out.x, out.y, out.z);
		for (int i = 0; i < 10000; i++) {
			Scatter s = bsdf.scatter(rng, out);
			Vec3 in = s.direction;
			Spectrum f = bsdf.evaluate(out, in);
			float p = bsdf.pdf(out, in);
			// With cosine sampling the weight is (albedo / pi) |cos| / (|cos| / pi) = albedo: the
			// cosines cancel exactly, so only float rounding remains.
			Spectrum weight = f * std::abs(in.y) / p;
			bool unit = std::abs(glm::length(in) - 1.0f) < 1e-5f;
			bool same_side = in.y * out.y > 0.0f;
			bool attenuation_is_f = true, weight_is_albedo = true;
			for (int c = 0; c < 3; c++) {
				attenuation_is_f = attenuation_is_f && close(s.attenuation[c], f[c], 1e-6f);
				weight_is_albedo = weight_is_albedo && close(weight[c], ALBEDO[c], 1e-5f);
			}
			if (unit && same_side && attenuation_is_f && weight_is_albedo) continue;

			INFO("sample " << i << ": in_dir = (" << in.x << ", " << in.y << ", " << in.z << "), attenuation = ("
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
				     << ") must equal the albedo (" << ALBEDO.r << ", " << ALBEDO.g << ", " << ALBEDO.b
				     << ") for every cosine-weighted sample (pdf = " << p << ")");
				CHECK(weight_is_albedo);
			}
			break; // one sample explained is enough
		}
	}
}

TEST_CASE("Lambertian scatter: directions follow the cosine density |cos theta| / pi (chi-square), on both sides") {
	// Cells of equal solid angle: n_cos slices of cos theta in [-1, 1] times n_phi slices of phi.
	// The probability of cell [c0, c1] x [phi0, phi1] on out_dir's side is
	// integral |c| / pi dc dphi = |c1^2 - c0^2| / 2 * (2 pi / n_phi) / pi = |c1^2 - c0^2| / n_phi; across
	// the surface it is 0 and any sample there fails the test.
	constexpr size_t n_cos = 40, n_phi = 80, samples = 1000000;
	const double alpha = stats::sidak(0.01, OUT_DIRS.size()); // one chi-square test per out_dir
	BSDF_Lambertian bsdf{ALBEDO};
	for (size_t k = 0; k < OUT_DIRS.size(); k++) {
		Vec3 out = OUT_DIRS[k];
		CAPTURE(out.x, out.y, out.z);
		std::vector<double> observed(n_cos * n_phi, 0.0), expected(n_cos * n_phi, 0.0);
		for (size_t i = 0; i < n_cos; i++) {
			double c0 = -1.0 + 2.0 * double(i) / n_cos, c1 = -1.0 + 2.0 * double(i + 1) / n_cos;
			bool on_out_side = 0.5 * (c0 + c1) * out.y > 0.0;
			for (size_t j = 0; j < n_phi; j++) {
				expected[i * n_phi + j] = on_out_side ? samples * std::abs(c1 * c1 - c0 * c0) / n_phi : 0.0;
			}
		}
		RNG rng(2024, k);
		size_t invalid = 0;
		for (size_t n = 0; n < samples; n++) {
			Vec3 in = bsdf.scatter(rng, out).direction;
			if (!is_finite(in) || std::abs(glm::length(in) - 1.0f) > 1e-4f) {
				invalid++;
				continue;
			}
			double phi = std::atan2(double(in.z), double(in.x));
			if (phi < 0.0) phi += 2.0 * PI;
			size_t i = std::min(size_t((double(in.y) + 1.0) * 0.5 * n_cos), n_cos - 1);
			size_t j = std::min(size_t(phi / (2.0 * PI) * n_phi), n_phi - 1);
			observed[i * n_phi + j] += 1.0;
		}
		INFO(invalid << " of " << samples << " sampled directions were not finite unit vectors");
		REQUIRE(invalid == 0);
		stats::Chi2_Result r = stats::chi2_test(observed, expected);
		INFO("chi-square " << r.statistic << " with " << r.dof << " degrees of freedom, p-value " << r.p_value
		     << " (reject below " << alpha << "); " << r.observed_in_impossible_cells
		     << " samples landed across the surface from out_dir (" << side(out) << ")");
		INFO("the sampled in_dir must be distributed like cos(theta) / pi on out_dir's side: Malley's method "
		     "(uniform disk point lifted onto the hemisphere), handout §4.1");
		CHECK(r.observed_in_impossible_cells == 0.0);
		CHECK(r.p_value >= alpha);
	}
}

// Task 5, handouts §5.1 and §5.4: BSDF_Mirror and BSDF_Glass scatter (material.h). Both are
// discrete: Scatter::attenuation is the whole weight of the sample.
#include "material.h"
#include "directions.h"
#include "statistics.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

namespace {
using task5::direction;
using task5::str;
using task5::PI;

const Spectrum REFLECTANCE{0.9f, 0.8f, 0.7f}, TRANSMITTANCE{0.6f, 0.5f, 0.4f};

bool same(Spectrum a, Spectrum b) {
	return glm::length(a - b) <= 1e-6f * glm::length(b);
}

// The refracted direction by Snell's law in double precision (no total internal reflection).
Vec3 snell(Vec3 out, double ior) {
	double eta = out.y > 0.0f ? 1.0 / ior : ior;
	double cos_in = std::sqrt(1.0 - eta * eta * (1.0 - double(out.y) * out.y));
	return Vec3{float(-eta * out.x), float(out.y > 0.0f ? -cos_in : cos_in), float(-eta * out.z)};
}

} // namespace

TEST_CASE("Mirror scatter: in_dir = reflect(out_dir) exactly, attenuation = reflectance, from both sides") {
	BSDF_Mirror mirror{REFLECTANCE};
	RNG rng(5);
	for (Vec3 out : {direction(0.0, 0.0), direction(40.0, 1.0), direction(88.0, 2.0), direction(30.0, 3.0, true)}) {
		Scatter s = mirror.scatter(rng, out);
		INFO("mirror scatter of out_dir " << str(out) << " returned in_dir " << str(s.direction) << ", expected "
		     << str(Vec3{-out.x, out.y, -out.z}) << " = reflect(out_dir) (handout §5.1)");
		CHECK(s.direction.x == -out.x);
		CHECK(s.direction.y == out.y);
		CHECK(s.direction.z == -out.z);
		INFO("attenuation " << str(s.attenuation) << ", expected the reflectance " << str(REFLECTANCE)
		     << ": a discrete BSDF's attenuation is the whole sample weight (material.h)");
		CHECK(s.attenuation == REFLECTANCE);
	}
}

TEST_CASE("Glass scatter: reflects with probability F and refracts with 1 - F (binomial test at each angle)") {
	struct Angle {
		double theta;
		bool inside;
		double F; // testing-anchors §4, exact Fresnel for index 1.5
	};
	const Angle angles[] = {
		{0.0, false, 0.040000}, {45.0, false, 0.050240}, {56.3099, false, 0.073964}, {80.0, false, 0.387704},
		{0.0, true, 0.040000},  {20.0, true, 0.041729},  {40.0, true, 0.245291},
	};
	const size_t trials = 200000;
	const double z_max = stats::two_sided_z(stats::sidak(0.01, std::size(angles)));
	BSDF_Glass glass{REFLECTANCE, TRANSMITTANCE, 1.5f};
	RNG rng(55, 5);
	for (const Angle& a : angles) {
		Vec3 out = direction(a.theta, 0.3 + a.theta, a.inside);
		Vec3 refracted = snell(out, 1.5);
		CAPTURE(a.theta, a.inside);
		size_t reflections = 0;
		for (size_t i = 0; i < trials; i++) {
			Scatter s = glass.scatter(rng, out);
			bool reflected = s.direction.y * out.y > 0.0f;
			reflections += reflected;
			Vec3 expected = reflected ? Vec3{-out.x, out.y, -out.z} : refracted;
			Spectrum weight = reflected ? REFLECTANCE : TRANSMITTANCE;
			if (glm::length(s.direction - expected) > 1e-5f || !same(s.attenuation, weight)) {
				INFO("sample " << i << " from " << (a.inside ? "inside" : "outside") << " at " << a.theta
				     << " deg, out_dir " << str(out) << ": " << (reflected ? "reflected" : "refracted")
				     << " to " << str(s.direction) << " with attenuation " << str(s.attenuation) << ", expected "
				     << str(expected) << " with attenuation " << str(weight)
				     << (reflected ? " (the reflectance)" : " (the transmittance)")
				     << ": the probabilities F and 1 - F cancel the Fresnel weights (handout §5.4)");
				FAIL_CHECK("glass scatter returned a wrong direction or attenuation");
				break;
			}
		}
		double z = stats::binomial_z(reflections, trials, a.F);
		INFO(reflections << " reflections in " << trials << " samples from " << (a.inside ? "inside" : "outside")
		     << " at " << a.theta << " deg: frequency " << double(reflections) / trials << ", expected F = " << a.F
		     << " (z = " << z << ", allowed |z| < " << z_max << "). Reflect with probability fresnel(out_dir.y, ior), "
		        "the exact Fresnel reflectance (handout §5.3, §5.4)");
		CHECK(std::abs(z) < z_max);
	}
}

TEST_CASE("Glass scatter: beyond the critical angle inside, every sample reflects") {
	BSDF_Glass glass{REFLECTANCE, TRANSMITTANCE, 1.5f};
	RNG rng(56);
	for (double theta : {42.0, 60.0, 85.0}) {
		Vec3 out = direction(theta, 2.0, true);
		size_t refractions = 0;
		for (int i = 0; i < 10000; i++) {
			Scatter s = glass.scatter(rng, out);
			if (!(s.direction.y * out.y > 0.0f) || glm::length(s.direction - Vec3{-out.x, out.y, -out.z}) > 1e-5f ||
			    !same(s.attenuation, REFLECTANCE))
				refractions++;
		}
		INFO(refractions << " of 10000 samples at " << theta
		     << " deg inside the glass were not reflect(out_dir) with the reflectance: beyond the critical angle "
		        "41.81 deg there is total internal reflection (handout §5.2)");
		CHECK(refractions == 0);
	}
}

TEST_CASE("Glass with index of refraction 1 is invisible: every sample continues straight, in_dir = -out_dir") {
	// F = 0 at every angle, so a correct glass never reflects (one float rounding could make F ~1e-16,
	// which reflects with probability 2^-24 per sample: not in these 1500 fixed-seed samples).
	BSDF_Glass glass{REFLECTANCE, TRANSMITTANCE, 1.0f};
	RNG rng(57);
	for (Vec3 out : {direction(0.0, 0.0), direction(50.0, 1.0), direction(80.0, 2.0, true)}) {
		int wrong = 0;
		Scatter s;
		for (int i = 0; i < 500; i++) {
			s = glass.scatter(rng, out);
			if (glm::length(s.direction + out) > 1e-5f || !same(s.attenuation, TRANSMITTANCE)) wrong++;
		}
		INFO(wrong << " of 500 samples of out_dir " << str(out) << " with index 1 did not pass straight through with "
		     "the transmittance (last: " << str(s.direction) << ", attenuation " << str(s.attenuation) << ")");
		CHECK(wrong == 0);
	}
}

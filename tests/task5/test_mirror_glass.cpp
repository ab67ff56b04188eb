// Task 5, handouts §5.1 and §5.4: BSDF_Mirror and BSDF_Glass scatter (material.h). Both are
// discrete: Scatter::attenuation is the whole weight of the sample. The student's scatter runs in
// the subject (grading/judge/protocol.h) with the generators chosen here; expected directions are
// the reference's reflect and refract. With a grading seed the colours, directions, indices of
// refraction and generator seeds are drawn from it.
#include "directions.h"
#include "judge.h"
#include "material.h"
#include "statistics.h"

#include "lab_catch2.h"

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace {
using task5::direction;
using task5::str;
using protocol::BSDF_Scatter;

struct Colours {
	Spectrum reflectance{0.9f, 0.8f, 0.7f}, transmittance{0.6f, 0.5f, 0.4f};
};

Colours colours(std::optional<RNG>& secret) {
	Colours c;
	if (!secret) return c;
	for (Spectrum* s : {&c.reflectance, &c.transmittance}) {
		*s = Spectrum{float(task5::uniform(*secret, 0.05, 1.0)), float(task5::uniform(*secret, 0.05, 1.0)),
		              float(task5::uniform(*secret, 0.05, 1.0))};
	}
	return c;
}

bool same(Spectrum a, Spectrum b) {
	return glm::length(a - b) <= 1e-6f * glm::length(b);
}

// `bsdf`.scatter of each out_dir, `count` times each, from one generator seeded with `seed` (and
// `stream`), in that order.
std::vector<Scatter> student_scatter(const BSDF& bsdf, const std::vector<Vec3>& out_dirs, size_t count, uint64_t seed,
                                     uint64_t stream = 0) {
	BSDF_Scatter request{bsdf, {}, RNG_State::of(RNG(seed, stream))};
	for (Vec3 out : out_dirs) request.out_dirs.insert(request.out_dirs.end(), count, out);
	return judge::ask(request);
}

// The exact refracted direction (Snell, in double; the grader only refracts below the critical
// angle), never the reference's float answer.
Vec3 exact_refract(Vec3 out, float ior) {
	return Vec3(*task5::exact_refraction(out, ior));
}

std::string degrees(double theta) {
	std::ostringstream text;
	text.precision(4);
	text << theta;
	return text.str();
}

} // namespace

TEST_CASE("Mirror scatter: in_dir = reflect(out_dir) exactly, attenuation = reflectance, from both sides", "[id:t5.mirror.scatter][fn:Mirror::scatter][uses:reflect]") {
	std::optional<RNG> secret = judge::secret_inputs();
	const Spectrum reflectance = colours(secret).reflectance;
	std::vector<Vec3> dirs{direction(0.0, 0.0), direction(40.0, 1.0), direction(88.0, 2.0), direction(30.0, 3.0, true)};
	if (secret) {
		for (Vec3& d : dirs) d = direction(task5::uniform(*secret, 0.0, 89.0), task5::random_azimuth(*secret), d.y < 0.0f);
	}
	std::vector<Scatter> samples = student_scatter(BSDF(BSDF_Mirror{reflectance}), dirs, 1, judge::seed_or_public(secret, 5));
	for (size_t i = 0; i < dirs.size(); i++) {
		Vec3 out = dirs[i], expected = reflect(out);
		const Scatter& s = samples[i];
		INFO("mirror scatter of out_dir " << str(out) << " returned in_dir " << str(s.direction) << ", expected "
		     << str(expected) << " = reflect(out_dir) (handout §5.1)");
		CHECK(s.direction.x == expected.x);
		CHECK(s.direction.y == expected.y);
		CHECK(s.direction.z == expected.z);
		INFO("attenuation " << str(s.attenuation) << ", expected the reflectance " << str(reflectance)
		     << ": a discrete BSDF's attenuation is the whole sample weight (material.h)");
		CHECK(s.attenuation == reflectance);
	}
}

TEST_CASE("Glass scatter: reflects with probability F and refracts with 1 - F (binomial test at each angle)", "[id:t5.glass.reflect-or-refract][statistical:7][fn:Glass::scatter][uses:fresnel][uses:refract][uses:reflect]") {
	struct Angle {
		double theta;
		bool inside;
		double F; // exact Fresnel for index 1.5 (handout §5.3)
	};
	std::optional<RNG> secret = judge::secret_inputs();
	const Colours c = colours(secret);
	float ior = 1.5f;
	std::vector<Angle> angles{
		{0.0, false, 0.040000}, {45.0, false, 0.050240}, {56.3099, false, 0.073964}, {80.0, false, 0.387704},
		{0.0, true, 0.040000},  {20.0, true, 0.041729},  {40.0, true, 0.245291},
	};
	if (secret) {
		// Four angles outside, three inside below the critical angle; F is exact (task5::exact_fresnel).
		ior = task5::random_ior(*secret);
		double inside_max = task5::critical_angle_degrees(ior) - 2.0;
		for (Angle& a : angles) {
			a.theta = task5::uniform(*secret, 0.0, a.inside ? inside_max : 85.0);
			a.F = task5::exact_fresnel(direction(a.theta, 0.3 + a.theta, a.inside).y, ior);
		}
	}
	const size_t trials = 200000;
	std::vector<Vec3> out_dirs;
	for (const Angle& a : angles) out_dirs.push_back(direction(a.theta, 0.3 + a.theta, a.inside));
	std::vector<Scatter> samples = student_scatter(BSDF(BSDF_Glass{c.reflectance, c.transmittance, ior}), out_dirs,
	                                               trials, judge::seed_or_public(secret, 55), 5);
	for (size_t k = 0; k < angles.size(); k++) {
		const Angle& a = angles[k];
		Vec3 out = out_dirs[k];
		Vec3 refracted = exact_refract(out, ior);
		CAPTURE(a.theta, a.inside);
		// Every sample counts towards the frequency; only the first wrong one is described.
		size_t reflections = 0;
		bool described = false;
		for (size_t i = 0; i < trials; i++) {
			const Scatter& s = samples[k * trials + i];
			bool reflected = s.direction.y * out.y > 0.0f;
			reflections += reflected;
			Vec3 expected = reflected ? reflect(out) : refracted;
			Spectrum weight = reflected ? c.reflectance : c.transmittance;
			if (!described && (glm::length(s.direction - expected) > 1e-5f || !same(s.attenuation, weight))) {
				described = true;
				INFO("sample " << i << " from " << (a.inside ? "inside" : "outside") << " at " << a.theta
				     << " deg, out_dir " << str(out) << ": " << (reflected ? "reflected" : "refracted")
				     << " to " << str(s.direction) << " with attenuation " << str(s.attenuation) << ", expected "
				     << str(expected) << " with attenuation " << str(weight)
				     << (reflected ? " (the reflectance)" : " (the transmittance)")
				     << ": the probabilities F and 1 - F cancel the Fresnel weights (handout §5.4)");
				FAIL_CHECK("glass scatter returned a wrong direction or attenuation");
			}
		}
		double z = stats::binomial_z(reflections, trials, a.F);
		const double z_max = judge::z_critical(); // one z-test per angle
		INFO(reflections << " reflections in " << trials << " samples from " << (a.inside ? "inside" : "outside")
		     << " at " << a.theta << " deg: frequency " << double(reflections) / trials << ", expected F = " << a.F
		     << " (z = " << z << ", allowed |z| < " << z_max << "). Reflect with probability fresnel(out_dir.y, ior), "
		        "the exact Fresnel reflectance (handout §5.3, §5.4)");
		CHECK(std::abs(z) < z_max);
	}
}

TEST_CASE("Glass scatter: beyond the critical angle inside, every sample reflects", "[id:t5.glass.total-reflection][fn:Glass::scatter][uses:fresnel][uses:refract][uses:reflect]") {
	std::optional<RNG> secret = judge::secret_inputs();
	const Colours c = colours(secret);
	float ior = 1.5f;
	std::vector<double> thetas{42.0, 60.0, 85.0};
	double phi = 2.0;
	if (secret) {
		ior = task5::random_ior(*secret);
		for (double& theta : thetas) theta = task5::uniform(*secret, task5::critical_angle_degrees(ior) + 0.2, 89.5);
		phi = task5::random_azimuth(*secret);
	}
	std::vector<Vec3> out_dirs;
	for (double theta : thetas) out_dirs.push_back(direction(theta, phi, true));
	const size_t count = 10000;
	std::vector<Scatter> samples = student_scatter(BSDF(BSDF_Glass{c.reflectance, c.transmittance, ior}), out_dirs,
	                                               count, judge::seed_or_public(secret, 56));
	for (size_t k = 0; k < thetas.size(); k++) {
		Vec3 out = out_dirs[k];
		size_t refractions = 0;
		for (size_t i = 0; i < count; i++) {
			const Scatter& s = samples[k * count + i];
			if (!(s.direction.y * out.y > 0.0f) || glm::length(s.direction - reflect(out)) > 1e-5f ||
			    !same(s.attenuation, c.reflectance))
				refractions++;
		}
		INFO(refractions << " of 10000 samples at " << thetas[k] << " deg inside the glass were not reflect(out_dir) "
		     "with the reflectance: beyond the critical angle " << degrees(task5::critical_angle_degrees(ior))
		     << " deg there is total internal reflection (handout §5.2)");
		CHECK(refractions == 0);
	}
}

TEST_CASE("Glass with index of refraction 1 is invisible: every sample continues straight, in_dir = -out_dir", "[id:t5.glass.index-one][fn:Glass::scatter][uses:fresnel][uses:refract]") {
	// F = 0 at every angle, so a correct glass never reflects (one float rounding could make F ~1e-16,
	// which reflects with probability 2^-24 per sample: not in these 1500 samples, whose generator
	// keeps its public seed under a grading seed too; only the directions and colours are drawn).
	std::optional<RNG> secret = judge::secret_inputs();
	const Colours c = colours(secret);
	std::vector<Vec3> dirs{direction(0.0, 0.0), direction(50.0, 1.0), direction(80.0, 2.0, true)};
	if (secret) {
		for (Vec3& d : dirs) d = direction(task5::uniform(*secret, 0.0, 85.0), task5::random_azimuth(*secret), d.y < 0.0f);
	}
	const size_t count = 500;
	std::vector<Scatter> samples =
		student_scatter(BSDF(BSDF_Glass{c.reflectance, c.transmittance, 1.0f}), dirs, count, 57);
	for (size_t k = 0; k < dirs.size(); k++) {
		Vec3 out = dirs[k];
		int wrong = 0;
		Scatter s;
		for (size_t i = 0; i < count; i++) {
			s = samples[k * count + i];
			if (glm::length(s.direction + out) > 1e-5f || !same(s.attenuation, c.transmittance)) wrong++;
		}
		INFO(wrong << " of 500 samples of out_dir " << str(out) << " with index 1 did not pass straight through with "
		     "the transmittance (last: " << str(s.direction) << ", attenuation " << str(s.attenuation) << ")");
		CHECK(wrong == 0);
	}
}

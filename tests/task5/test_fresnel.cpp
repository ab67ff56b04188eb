// Task 5, handout §5.3: the exact unpolarised Fresnel reflectance of a dielectric boundary,
// fresnel(cos_theta, index_of_refraction), cos_theta > 0 outside (vacuum), < 0 inside. The student's
// fresnel runs in the subject (grading/judge/protocol.h).
//
// Expected values of the public cases: computed independently in double precision from r_s, r_p
// and F = (r_s^2 + r_p^2) / 2 (handout §5.3), matching the values of Mitsuba 3's test_fresnel.
// With a grading seed the angles (and, where the test's name does not fix it, the index) are
// drawn from it and the expected values are the same formula in double for the float cos_theta
// the student gets (task5::exact_fresnel), never the reference's float answer.
// Tolerance 1e-5: the exact formula evaluated in float is within ~4e-7 of these values at every
// angle tested (including 40 degrees inside, where F is steep); Schlick's approximation is not
// accepted: it is off by 8e-3 at 45 degrees, 1.7e-2 at Brewster's angle and 2.2e-2 at 80 degrees.
#include "directions.h"
#include "judge.h"
#include "material.h"

#include "lab_catch2.h"

#include <cmath>
#include <vector>

namespace {

using task5::PI;
constexpr double TOLERANCE = 1e-5;

float cos_degrees(double theta) {
	return float(std::cos(theta * PI / 180.0));
}

struct Reference {
	double theta; // degrees
	double F;
};

std::vector<float> student_fresnel(const std::vector<protocol::Fresnel::Query>& queries) {
	return judge::ask(protocol::Fresnel{queries});
}

// With a grading seed: `count` angles uniform in [lo, hi] degrees, with the exact F for index 1.5
// from outside (sign +1) or inside (sign -1).
void add_drawn(std::vector<Reference>& table, RNG& rng, int count, double lo, double hi, float sign) {
	for (int i = 0; i < count; i++) {
		double theta = task5::uniform(rng, lo, hi);
		table.push_back({theta, task5::exact_fresnel(sign * cos_degrees(theta), 1.5)});
	}
}

} // namespace

TEST_CASE("fresnel from outside (vacuum into glass of index 1.5) matches the exact Fresnel equations", "[id:t5.fresnel.outside][fn:fresnel]") {
	std::optional<RNG> secret = judge::secret_inputs();
	std::vector<Reference> table{
		{0.0, 0.040000}, {30.0, 0.041523}, {45.0, 0.050240}, {56.3099, 0.073964} /* Brewster: r_p = 0 */,
		{60.0, 0.089187}, {70.0, 0.171043}, {80.0, 0.387704}, {85.0, 0.612800}, {89.0, 0.904185},
	};
	if (secret) {
		table.clear();
		add_drawn(table, *secret, 9, 0.0, 89.0, 1.0f);
	}
	std::vector<protocol::Fresnel::Query> queries;
	for (const Reference& r : table) queries.push_back({cos_degrees(r.theta), 1.5f});
	std::vector<float> answers = student_fresnel(queries);
	for (size_t i = 0; i < table.size(); i++) {
		const Reference& r = table[i];
		float F = answers[i];
		INFO("fresnel(cos(" << r.theta << " deg), 1.5) from outside = " << F << ", expected " << r.F
		     << " (exact unpolarised Fresnel, F = (r_s^2 + r_p^2) / 2; Schlick's approximation is not accurate "
		        "enough for the grader, handout §5.3)");
		CHECK(std::abs(F - r.F) <= TOLERANCE);
	}
}

TEST_CASE("fresnel from inside (glass of index 1.5 into vacuum) matches the exact equations, and is 1 beyond "
          "the critical angle 41.81 degrees", "[id:t5.fresnel.inside][fn:fresnel]") {
	std::optional<RNG> secret = judge::secret_inputs();
	std::vector<Reference> table{
		{0.0, 0.040000}, {10.0, 0.040083}, {20.0, 0.041729}, {30.0, 0.055190}, {33.69, 0.073964},
		{40.0, 0.245291}, {41.9, 1.0}, {45.0, 1.0}, {60.0, 1.0}, {89.0, 1.0},
	};
	if (secret) {
		table.clear();
		add_drawn(table, *secret, 6, 0.0, 40.0, -1.0f); // not closer to 41.81, where F is steep: as public
		add_drawn(table, *secret, 4, 41.9, 89.0, -1.0f);
	}
	std::vector<protocol::Fresnel::Query> queries;
	for (const Reference& r : table) queries.push_back({-cos_degrees(r.theta), 1.5f});
	std::vector<float> answers = student_fresnel(queries);
	for (size_t i = 0; i < table.size(); i++) {
		const Reference& r = table[i];
		float F = answers[i];
		INFO("fresnel(-cos(" << r.theta << " deg), 1.5), i.e. from inside the glass, = " << F << ", expected " << r.F
		     << (r.F == 1.0 ? ": beyond the critical angle asin(1/1.5) = 41.81 deg light is totally reflected"
		                    : ": from inside, light goes from index 1.5 into index 1 (handout §5.3)"));
		CHECK(std::abs(F - r.F) <= TOLERANCE);
	}
}

TEST_CASE("fresnel is the same for a direction and its refracted partner (both sides agree)", "[id:t5.fresnel.both-sides][fn:fresnel]") {
	// Reflectance is reciprocal: F(theta_i from outside) = F(theta_t from inside) when
	// sin(theta_i) = n sin(theta_t) (the reference's refract gives theta_t). A version that ignores
	// which side it is on fails this.
	std::optional<RNG> secret = judge::secret_inputs();
	std::vector<double> thetas{5.0, 25.0, 50.0, 70.0, 85.0};
	float ior = 1.5f;
	if (secret) {
		ior = task5::random_ior(*secret);
		// Up to 85 degrees, as public: nearer grazing the inside angle is near critical, where F's
		// float rounding differs by more than the tolerance between the two sides.
		for (double& theta : thetas) theta = task5::uniform(*secret, 0.0, 85.0);
	}
	std::vector<protocol::Fresnel::Query> queries;
	for (double theta_i : thetas) {
		Vec3 out = task5::direction(theta_i, 0.0);
		bool internal = false;
		Vec3 partner = refract(out, ior, internal); // inside, y < 0
		queries.push_back({out.y, ior});
		queries.push_back({partner.y, ior});
	}
	std::vector<float> answers = student_fresnel(queries);
	for (size_t i = 0; i < thetas.size(); i++) {
		double theta_t = std::acos(-double(queries[2 * i + 1].cos_theta)) * 180.0 / PI;
		float outside = answers[2 * i], inside = answers[2 * i + 1];
		// The partner's cos_theta is a float, rounded: the exact F differs between the two inputs by
		// what that rounding moves it (much near the critical angle, where F is steep), on top of the
		// tolerance of each.
		double rounding = std::abs(task5::exact_fresnel(queries[2 * i].cos_theta, ior) -
		                           task5::exact_fresnel(queries[2 * i + 1].cos_theta, ior));
		INFO("outside at " << thetas[i] << " deg: F = " << outside << "; inside at the refracted angle " << theta_t
		     << " deg: F = " << inside << ". They must be equal: the same boundary, crossed either way");
		CHECK(std::abs(outside - inside) <= 2.0 * TOLERANCE + rounding);
	}
}

TEST_CASE("fresnel with index of refraction 1 is 0: there is no boundary to reflect from", "[id:t5.fresnel.index-one][fn:fresnel]") {
	std::optional<RNG> secret = judge::secret_inputs();
	std::vector<double> thetas{0.0, 30.0, 60.0, 85.0};
	if (secret) {
		for (double& theta : thetas) theta = task5::uniform(*secret, 0.0, 89.0);
	}
	std::vector<protocol::Fresnel::Query> queries;
	for (double theta : thetas) {
		for (float sign : {1.0f, -1.0f}) queries.push_back({sign * cos_degrees(theta), 1.0f});
	}
	std::vector<float> answers = student_fresnel(queries);
	for (size_t i = 0; i < queries.size(); i++) {
		INFO("fresnel(" << queries[i].cos_theta << ", 1.0) = " << answers[i] << ", expected 0");
		CHECK(std::abs(answers[i]) <= TOLERANCE);
	}
}

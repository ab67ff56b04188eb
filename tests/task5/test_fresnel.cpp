// Task 5, handout §5.3: the exact unpolarised Fresnel reflectance of a dielectric boundary,
// fresnel(cos_theta, index_of_refraction), cos_theta > 0 outside (vacuum), < 0 inside.
//
// Expected values: docs testing-anchors §4 (computed there independently in double precision from
// r_s, r_p and F = (r_s^2 + r_p^2) / 2, and matching Mitsuba 3's test_fresnel values of §2.3).
// Tolerance 1e-5: the exact formula evaluated in float is within ~4e-7 of these values at every
// angle tested (including 40 degrees inside, where F is steep); Schlick's approximation is not
// accepted: it is off by 8e-3 at 45 degrees, 1.7e-2 at Brewster's angle and 2.2e-2 at 80 degrees.
#include "material.h"

#include <catch2/catch.hpp>

#include <cmath>

namespace {

constexpr double PI = 3.14159265358979323846;
constexpr double TOLERANCE = 1e-5;

float cos_degrees(double theta) {
	return float(std::cos(theta * PI / 180.0));
}

struct Reference {
	double theta; // degrees
	double F;
};

} // namespace

TEST_CASE("fresnel from outside (vacuum into glass of index 1.5) matches the exact Fresnel equations") {
	const Reference table[] = {
		{0.0, 0.040000}, {30.0, 0.041523}, {45.0, 0.050240}, {56.3099, 0.073964} /* Brewster: r_p = 0 */,
		{60.0, 0.089187}, {70.0, 0.171043}, {80.0, 0.387704}, {85.0, 0.612800}, {89.0, 0.904185},
	};
	for (const Reference& r : table) {
		float F = fresnel(cos_degrees(r.theta), 1.5f);
		INFO("fresnel(cos(" << r.theta << " deg), 1.5) from outside = " << F << ", expected " << r.F
		     << " (exact unpolarised Fresnel, F = (r_s^2 + r_p^2) / 2; Schlick's approximation is not accurate "
		        "enough for the grader, handout §5.3)");
		CHECK(std::abs(F - r.F) <= TOLERANCE);
	}
}

TEST_CASE("fresnel from inside (glass of index 1.5 into vacuum) matches the exact equations, and is 1 beyond "
          "the critical angle 41.81 degrees") {
	const Reference table[] = {
		{0.0, 0.040000}, {10.0, 0.040083}, {20.0, 0.041729}, {30.0, 0.055190}, {33.69, 0.073964},
		{40.0, 0.245291}, {41.9, 1.0}, {45.0, 1.0}, {60.0, 1.0}, {89.0, 1.0},
	};
	for (const Reference& r : table) {
		float F = fresnel(-cos_degrees(r.theta), 1.5f);
		INFO("fresnel(-cos(" << r.theta << " deg), 1.5), i.e. from inside the glass, = " << F << ", expected " << r.F
		     << (r.F == 1.0 ? ": beyond the critical angle asin(1/1.5) = 41.81 deg light is totally reflected"
		                    : ": from inside, light goes from index 1.5 into index 1 (handout §5.3)"));
		CHECK(std::abs(F - r.F) <= TOLERANCE);
	}
}

TEST_CASE("fresnel is the same for a direction and its refracted partner (both sides agree)") {
	// Reflectance is reciprocal: F(theta_i from outside) = F(theta_t from inside) when
	// sin(theta_i) = 1.5 sin(theta_t). A version that ignores which side it is on fails this.
	for (double theta_i : {5.0, 25.0, 50.0, 70.0, 85.0}) {
		double theta_t = std::asin(std::sin(theta_i * PI / 180.0) / 1.5) * 180.0 / PI;
		float outside = fresnel(cos_degrees(theta_i), 1.5f);
		float inside = fresnel(-cos_degrees(theta_t), 1.5f);
		INFO("outside at " << theta_i << " deg: F = " << outside << "; inside at the refracted angle " << theta_t
		     << " deg: F = " << inside << ". They must be equal: the same boundary, crossed either way");
		CHECK(std::abs(outside - inside) <= TOLERANCE);
	}
}

TEST_CASE("fresnel with index of refraction 1 is 0: there is no boundary to reflect from") {
	for (double theta : {0.0, 30.0, 60.0, 85.0}) {
		for (float sign : {1.0f, -1.0f}) {
			float F = fresnel(sign * cos_degrees(theta), 1.0f);
			INFO("fresnel(" << sign * cos_degrees(theta) << ", 1.0) = " << F << ", expected 0");
			CHECK(std::abs(F) <= TOLERANCE);
		}
	}
}

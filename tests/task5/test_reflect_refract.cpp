// Task 5, handout §5.1-§5.2: reflect and refract in the local frame (normal +y; out_dir and the
// returned in_dir both point away from the surface). Expected directions are computed here in
// double precision from the law of reflection and Snell's law.
#include "directions.h"
#include "material.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

namespace {
using task5::direction;
using task5::str;
using task5::PI;

constexpr float IOR = 1.5f;

// Snell's law for the lab's convention: out_dir outside (y > 0) is in vacuum and in_dir inside
// (index IOR), or the reverse. Returns false on total internal reflection.
bool snell(glm::dvec3 out, double ior, glm::dvec3& in) {
	double eta = out.y > 0.0 ? 1.0 / ior : ior; // n_out / n_in
	double cos2 = 1.0 - eta * eta * (1.0 - out.y * out.y);
	if (cos2 < 0.0) return false;
	in = glm::dvec3(-eta * out.x, out.y > 0.0 ? -std::sqrt(cos2) : std::sqrt(cos2), -eta * out.z);
	return true;
}

} // namespace

TEST_CASE("reflect mirrors a direction about the normal (0, 1, 0): (x, y, z) -> (-x, y, -z), exactly") {
	for (Vec3 d : {Vec3{0.0f, 1.0f, 0.0f}, direction(30.0, 0.4), direction(75.0, 2.0), direction(89.0, -1.0),
	               direction(50.0, 3.0, true), Vec3{0.6f, 0.0f, 0.8f}}) {
		Vec3 r = reflect(d);
		INFO("reflect" << str(d) << " returned " << str(r) << ", expected " << str(Vec3{-d.x, d.y, -d.z})
		     << ": the normal component (y) stays, the tangential ones (x, z) change sign (handout §5.1)");
		CHECK(r.x == -d.x);
		CHECK(r.y == d.y);
		CHECK(r.z == -d.z);
	}
}

TEST_CASE("refract obeys Snell's law from both sides: n_out sin(theta_out) = n_in sin(theta_in), to 1e-5") {
	// From outside every angle refracts; from inside, angles below the critical angle
	// asin(1 / 1.5) = 41.81 degrees do.
	int checked = 0;
	for (bool inside : {false, true}) {
		double max_theta = inside ? 41.5 : 89.5;
		for (int i = 0; i <= 40; i++) {
			double theta = max_theta * i / 40.0;
			double phi = 0.37 + 0.91 * i; // a different azimuth for each angle
			Vec3 out = direction(theta, phi, inside);
			bool internal = true;
			Vec3 in = refract(out, IOR, internal);
			glm::dvec3 expected;
			REQUIRE(snell(glm::dvec3(out), IOR, expected));
			INFO("refract" << str(out) << " (from " << (inside ? "inside" : "outside") << ", theta = " << theta
			     << " degrees, index 1.5) returned " << str(in) << ", expected " << str(Vec3(expected)));
			{
				INFO("was_internal must be false: below the critical angle light refracts (handout §5.2)");
				CHECK_FALSE(internal);
			}
			{
				INFO("the refracted in_dir must be unit length");
				CHECK(std::abs(glm::length(in) - 1.0f) < 1e-5f);
			}
			{
				INFO("in_dir must lie on the other side of the surface than out_dir (y changes sign)");
				CHECK(in.y * out.y < 0.0f);
			}
			{
				double n_out = inside ? IOR : 1.0, n_in = inside ? 1.0 : IOR;
				double sin_out = std::hypot(out.x, out.z), sin_in = std::hypot(in.x, in.z);
				INFO("Snell: n_out sin(theta_out) = " << n_out * sin_out << " but n_in sin(theta_in) = " << n_in * sin_in
				     << ": which side is vacuum (index 1) and which glass (index 1.5)? out_dir.y > 0 means "
				        "out_dir is outside, in vacuum (handout §5.2)");
				CHECK(std::abs(n_out * sin_out - n_in * sin_in) < 1e-5);
			}
			{
				INFO("in_dir must equal the Snell direction: its tangential part points opposite to out_dir's "
				     "(the path goes through the surface), its y component is -sign(out.y) cos(theta_in)");
				CHECK(glm::length(glm::dvec3(in) - expected) < 1e-5);
			}
			checked++;
		}
	}
	CHECK(checked == 82);
}

TEST_CASE("refract: beyond the critical angle 41.81 degrees inside glass, total internal reflection") {
	for (double theta : {41.9, 45.0, 60.0, 80.0, 89.9}) {
		Vec3 out = direction(theta, 1.1, /*below=*/true);
		bool internal = false;
		Vec3 in = refract(out, IOR, internal);
		INFO("refract" << str(out) << " from inside glass of index 1.5 at " << theta
		     << " degrees, beyond the critical angle asin(1/1.5) = 41.81 degrees: cos^2(theta_t) < 0, so "
		        "was_internal must be true and the result reflect(out_dir) (handout §5.2); got "
		     << str(in) << ", was_internal = " << internal);
		CHECK(internal);
		CHECK(glm::length(in - Vec3{-out.x, out.y, -out.z}) < 1e-6f);
	}
	// Just below the critical angle light still escapes.
	bool internal = true;
	refract(direction(41.7, 0.2, true), IOR, internal);
	INFO("at 41.7 degrees inside, just below the critical angle, light refracts: was_internal must be false");
	CHECK_FALSE(internal);
	// From outside there is never total internal reflection.
	internal = true;
	refract(direction(89.9, 0.2), IOR, internal);
	INFO("from outside (vacuum into glass) there is never total internal reflection, even at 89.9 degrees");
	CHECK_FALSE(internal);
}

TEST_CASE("refract with index of refraction 1 passes straight through: in_dir = -out_dir") {
	for (Vec3 out : {direction(0.0, 0.0), direction(35.0, 1.0), direction(80.0, 2.5), direction(60.0, 4.0, true)}) {
		bool internal = true;
		Vec3 in = refract(out, 1.0f, internal);
		INFO("refract" << str(out) << ", 1.0) returned " << str(in) << ": with equal indices on both sides the "
		     "path continues in a straight line, in_dir = -out_dir = " << str(-out));
		CHECK_FALSE(internal);
		CHECK(glm::length(in + out) < 1e-6f);
	}
}

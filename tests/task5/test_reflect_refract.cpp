// Task 5, handout §5.1-§5.2: reflect and refract in the local frame (normal +y; out_dir and the
// returned in_dir both point away from the surface). The student's functions run in the subject
// (grading/judge/protocol.h); expected directions are exact (reflection's is exact in float, Snell's
// is computed in double for the float input, task5::exact_refraction), and the checks restate the
// law of reflection and Snell's law. With a grading seed the directions and (where the test's name
// does not fix it) the index of refraction are drawn from it.
#include "directions.h"
#include "judge.h"
#include "material.h"

#include "lab_catch2.h"

#include <cmath>
#include <string>
#include <vector>

namespace {
using task5::direction;
using task5::str;
using task5::PI;

constexpr float IOR = 1.5f;

using Refraction = protocol::Refract::Result;

std::vector<Refraction> student_refract(const std::vector<protocol::Refract::Query>& queries) {
	return judge::ask(protocol::Refract{queries});
}

} // namespace

TEST_CASE("reflect mirrors a direction about the normal (0, 1, 0): (x, y, z) -> (-x, y, -z), exactly", "[id:t5.reflect.mirror][fn:reflect]") {
	std::optional<RNG> secret = judge::secret_inputs();
	std::vector<Vec3> dirs{Vec3{0.0f, 1.0f, 0.0f}, direction(30.0, 0.4), direction(75.0, 2.0), direction(89.0, -1.0),
	                       direction(50.0, 3.0, true), Vec3{0.6f, 0.0f, 0.8f}};
	if (secret) {
		for (Vec3& d : dirs) d = direction(task5::uniform(*secret, 0.0, 180.0), task5::random_azimuth(*secret));
		dirs.back() = direction(90.0, task5::random_azimuth(*secret)); // in the surface: y = 0
	}
	std::vector<Vec3> reflected = judge::ask(protocol::Reflect{dirs});
	for (size_t i = 0; i < dirs.size(); i++) {
		Vec3 d = dirs[i], r = reflected[i], expected = reflect(d);
		INFO("reflect" << str(d) << " returned " << str(r) << ", expected " << str(expected)
		     << ": the normal component (y) stays, the tangential ones (x, z) change sign (handout §5.1)");
		CHECK(r.x == expected.x);
		CHECK(r.y == expected.y);
		CHECK(r.z == expected.z);
	}
}

TEST_CASE("refract obeys Snell's law from both sides: n_out sin(theta_out) = n_in sin(theta_in), to 1e-5", "[id:t5.refract.snell][fn:refract]") {
	// From outside every angle refracts; from inside, angles below the critical angle
	// (asin(1 / 1.5) = 41.81 degrees for the public index) do.
	std::optional<RNG> secret = judge::secret_inputs();
	const float ior = secret ? task5::random_ior(*secret) : IOR;
	std::vector<protocol::Refract::Query> queries;
	std::vector<double> thetas; // degrees from the normal
	for (bool inside : {false, true}) {
		double max_theta = inside ? (secret ? task5::critical_angle_degrees(ior) - 0.3 : 41.5) : 89.5;
		for (int i = 0; i <= 40; i++) {
			double theta = secret ? task5::uniform(*secret, 0.0, max_theta) : max_theta * i / 40.0;
			double phi = secret ? task5::random_azimuth(*secret) : 0.37 + 0.91 * i; // a different azimuth each
			queries.push_back({direction(theta, phi, inside), ior});
			thetas.push_back(theta);
		}
	}
	std::vector<Refraction> answers = student_refract(queries);
	int checked = 0;
	for (size_t n = 0; n < queries.size(); n++) {
		Vec3 out = queries[n].out_dir, in = answers[n].in_dir;
		bool inside = out.y < 0.0f, internal = answers[n].was_internal;
		double theta = thetas[n];
		// The exact Snell direction for the float input, in double (directions.h).
		std::optional<glm::dvec3> expected = task5::exact_refraction(out, ior);
		{
			INFO("grader self-check: " << str(out) << " refracts");
			REQUIRE(expected);
		}
		Vec3 shown(*expected);
		INFO("refract" << str(out) << " (from " << (inside ? "inside" : "outside") << ", theta = " << theta
		     << " degrees, index " << ior << ") returned " << str(in) << ", expected " << str(shown));
		{
			INFO("was_internal must be false: below the critical angle light refracts (handout §5.2)");
			CHECK_FALSE(internal);
		}
		{
			INFO("the refracted in_dir must be unit length");
			CHECK(std::abs(glm::length(in) - 1.0f) < 1e-5f);
		}
		{
			INFO("in_dir must lie on the other side of the surface than out_dir (y changes sign): refraction goes "
			     "through the surface (handout §5.2)");
			CHECK(in.y * out.y < 0.0f);
		}
		{
			double n_out = inside ? ior : 1.0, n_in = inside ? 1.0 : ior;
			double sin_out = std::hypot(out.x, out.z), sin_in = std::hypot(in.x, in.z);
			INFO("Snell: n_out sin(theta_out) = " << n_out * sin_out << " but n_in sin(theta_in) = " << n_in * sin_in
			     << ": which side is vacuum (index 1) and which glass (index " << ior << ")? out_dir.y > 0 means "
			        "out_dir is outside, in vacuum (handout §5.2)");
			CHECK(std::abs(n_out * sin_out - n_in * sin_in) < 1e-5);
		}
		{
			INFO("in_dir must equal the Snell direction: its tangential part points opposite to out_dir's "
			     "(the path goes through the surface), its y component is -sign(out.y) cos(theta_in) (handout §5.2)");
			CHECK(glm::length(glm::dvec3(in) - *expected) < 1e-5);
		}
		checked++;
	}
	CHECK(checked == 82);
}

TEST_CASE("refract: beyond the critical angle 41.81 degrees inside glass, total internal reflection", "[id:t5.refract.total-reflection][fn:refract]") {
	std::optional<RNG> secret = judge::secret_inputs();
	std::vector<double> thetas{41.9, 45.0, 60.0, 80.0, 89.9};
	double phi = 1.1;
	if (secret) {
		for (double& theta : thetas) theta = task5::uniform(*secret, 41.9, 89.9);
		phi = task5::random_azimuth(*secret);
	}
	std::vector<protocol::Refract::Query> queries;
	for (double theta : thetas) queries.push_back({direction(theta, phi, /*below=*/true), IOR});
	// Just below the critical angle light still escapes; from outside there is never total internal
	// reflection.
	queries.push_back({direction(41.7, 0.2, true), IOR});
	queries.push_back({direction(89.9, 0.2), IOR});
	std::vector<Refraction> answers = student_refract(queries);
	for (size_t i = 0; i < thetas.size(); i++) {
		Vec3 out = queries[i].out_dir, in = answers[i].in_dir;
		bool internal = answers[i].was_internal;
		INFO("refract" << str(out) << " from inside glass of index 1.5 at " << thetas[i]
		     << " degrees, beyond the critical angle asin(1/1.5) = 41.81 degrees: cos^2(theta_t) < 0, so "
		        "was_internal must be true and the result reflect(out_dir) (handout §5.2); got "
		     << str(in) << ", was_internal = " << internal);
		CHECK(internal);
		CHECK(glm::length(in - Vec3{-out.x, out.y, -out.z}) < 1e-6f); // reflect(out_dir), exactly
	}
	{
		INFO("at 41.7 degrees inside, just below the critical angle, light refracts: was_internal must be false");
		CHECK_FALSE(answers[thetas.size()].was_internal);
	}
	INFO("from outside (vacuum into glass) there is never total internal reflection, even at 89.9 degrees");
	CHECK_FALSE(answers[thetas.size() + 1].was_internal);
}

TEST_CASE("refract with index of refraction 1 passes straight through: in_dir = -out_dir", "[id:t5.refract.index-one][fn:refract]") {
	std::optional<RNG> secret = judge::secret_inputs();
	std::vector<Vec3> dirs{direction(0.0, 0.0), direction(35.0, 1.0), direction(80.0, 2.5), direction(60.0, 4.0, true)};
	if (secret) {
		for (Vec3& d : dirs) d = direction(task5::uniform(*secret, 0.0, 89.0), task5::random_azimuth(*secret), d.y < 0.0f);
	}
	std::vector<protocol::Refract::Query> queries;
	for (Vec3 out : dirs) queries.push_back({out, 1.0f});
	std::vector<Refraction> answers = student_refract(queries);
	for (size_t i = 0; i < dirs.size(); i++) {
		Vec3 out = dirs[i], in = answers[i].in_dir;
		INFO("refract" << str(out) << ", 1.0) returned " << str(in) << ": with equal indices on both sides the "
		     "path continues in a straight line, in_dir = -out_dir = " << str(-out));
		CHECK_FALSE(answers[i].was_internal);
		CHECK(glm::length(in + out) < 1e-6f);
	}
}

// Task 7 grader, handout §7.1: the equirectangular mapping between directions and uv.
#include "env_test_support.h"

#include "lab_catch2.h"

using namespace env_test;

namespace {
// Angular tolerance of float trigonometry, in uv units (1e-5 of a turn is 0.0036 degrees).
constexpr float UV_TOLERANCE = 1e-5f;

// The direction of film coordinates uv (handout §7.1: phi = 2 pi u, theta = pi v, +y up), in double
// for the float uv: the exact answer, never the reference's float one.
glm::dvec3 exact_direction(Vec2 uv) {
	double phi = 2.0 * M_PI * double(uv.x), theta = M_PI * double(uv.y);
	return {std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
}

// Distance between two u values on the circle (u = 0 and u = 1 are the same meridian).
float u_distance(float a, float b) {
	float d = std::abs(a - b);
	return std::min(d, 1.0f - d);
}

std::vector<Vec2> student_uvs(const std::vector<Vec3>& dirs) {
	return judge::ask(protocol::Direction_To_UV{dirs});
}
std::vector<Vec3> student_directions(const std::vector<Vec2>& uvs) {
	return judge::ask(protocol::UV_To_Direction{uvs});
}
} // namespace

TEST_CASE("direction_to_uv: known directions land where the convention puts them", "[id:t7.mapping.to-uv][task7][mapping][fn:direction_to_uv]") {
	struct Known {
		Vec3 dir;
		Vec2 uv;
		const char* name;
	};
	const Known known[] = {
		{{1, 0, 0}, {0.0f, 0.5f}, "+x (phi = 0)"},
		{{0, 0, 1}, {0.25f, 0.5f}, "+z (phi = pi / 2)"},
		{{-1, 0, 0}, {0.5f, 0.5f}, "-x (phi = pi)"},
		{{0, 0, -1}, {0.75f, 0.5f}, "-z (phi = 3 pi / 2)"},
		{glm::normalize(Vec3{1, 1, 1}), {0.125f, float(std::acos(1.0 / std::sqrt(3.0)) / M_PI)}, "(1, 1, 1) / sqrt 3"},
	};
	std::vector<Vec3> dirs;
	for (const Known& k : known) dirs.push_back(k.dir);
	dirs.push_back(Vec3{0, 1, 0});
	dirs.push_back(Vec3{0, -1, 0});
	std::vector<Vec2> uvs = student_uvs(dirs);
	for (size_t n = 0; n < std::size(known); n++) {
		const Known& k = known[n];
		Vec2 uv = uvs[n];
		INFO("direction_to_uv" << str(k.dir) << " [" << k.name << "] returned " << str(uv) << ", expected "
		                       << str(k.uv) << ": theta = acos(y) / pi, phi = atan2(z, x) / (2 pi) (handout §7.1)");
		CHECK(u_distance(uv.x, k.uv.x) <= UV_TOLERANCE);
		CHECK(std::abs(uv.y - k.uv.y) <= UV_TOLERANCE);
	}
	{
		Vec2 up = uvs[std::size(known)];
		INFO("direction_to_uv(+y) returned " << str(up) << ": straight up is theta = 0, so v = 0 (handout §7.1)");
		CHECK(std::abs(up.y) <= UV_TOLERANCE);
	}
	{
		Vec2 down = uvs[std::size(known) + 1];
		INFO("direction_to_uv(-y) returned " << str(down) << ": straight down is theta = pi, so v = 1 (handout §7.1)");
		CHECK(std::abs(down.y - 1.0f) <= UV_TOLERANCE);
	}
}

TEST_CASE("uv_to_direction: known uv give the directions of the convention", "[id:t7.mapping.to-direction][task7][mapping][fn:uv_to_direction]") {
	struct Known {
		Vec2 uv;
		Vec3 dir;
	};
	const Known known[] = {
		{{0.0f, 0.5f}, {1, 0, 0}},  {{0.25f, 0.5f}, {0, 0, 1}}, {{0.5f, 0.5f}, {-1, 0, 0}},
		{{0.75f, 0.5f}, {0, 0, -1}}, {{0.3f, 0.0f}, {0, 1, 0}}, {{0.6f, 1.0f}, {0, -1, 0}},
	};
	std::vector<Vec2> uvs;
	for (const Known& k : known) uvs.push_back(k.uv);
	std::vector<Vec3> dirs = student_directions(uvs);
	for (size_t n = 0; n < std::size(known); n++) {
		const Known& k = known[n];
		Vec3 d = dirs[n];
		INFO("uv_to_direction" << str(k.uv) << " returned " << str(d) << ", expected " << str(k.dir)
		                       << ": dir = (sin theta cos phi, cos theta, sin theta sin phi), theta = pi v, "
		                          "phi = 2 pi u (handout §7.1)");
		CHECK(glm::length(d - k.dir) <= 1e-5f);
	}
}

TEST_CASE("uv_to_direction and direction_to_uv are each other's inverse", "[id:t7.mapping.inverse][task7][mapping][fn:direction_to_uv][fn:uv_to_direction]") {
	RNG rng(judge::secret_seed_or(71));
	std::vector<Vec2> uvs;
	std::vector<Vec3> expected_dirs;
	for (int n = 0; n < 10000; n++) {
		// Away from the poles, where u is undefined.
		uvs.push_back(Vec2{rng.unit(), 0.01f + 0.98f * rng.unit()});
		expected_dirs.push_back(Vec3(exact_direction(uvs.back())));
	}
	std::vector<Vec3> dirs = student_directions(uvs);
	std::vector<Vec2> backs = student_uvs(expected_dirs);
	int bad_directions = 0, bad_round_trips = 0;
	std::string first_direction, first_round_trip;
	for (size_t n = 0; n < uvs.size(); n++) {
		Vec2 uv = uvs[n], back = backs[n];
		Vec3 d = dirs[n], expected = expected_dirs[n];
		if (!(glm::length(d - expected) <= 1e-5f)) {
			if (bad_directions++ == 0)
				first_direction = "uv_to_direction" + str(uv) + " = " + str(d) + ", expected " + str(expected);
		}
		if (!(u_distance(back.x, uv.x) <= UV_TOLERANCE && std::abs(back.y - uv.y) <= UV_TOLERANCE)) {
			if (bad_round_trips++ == 0)
				first_round_trip = "direction_to_uv" + str(expected) + " = " + str(back) + ", expected " + str(uv);
		}
	}
	{
		INFO("uv_to_direction must return the unit direction of the convention (handout §7.1); first failure of "
		     << bad_directions << ": " << first_direction);
		CHECK(bad_directions == 0);
	}
	{
		INFO("direction_to_uv must invert uv_to_direction (handout §7.1); first failure of " << bad_round_trips
		                                                                                    << ": " << first_round_trip);
		CHECK(bad_round_trips == 0);
	}
}

TEST_CASE("direction_to_uv: u stays in [0, 1) and v in [0, 1], also just below phi = 0", "[id:t7.mapping.uv-range][task7][mapping][fn:direction_to_uv]") {
	// atan2 returns angles in [-pi, pi]: negative angles need 2 pi added, and a tiny negative angle
	// plus 2 pi rounds to 2 pi, which is u = 1 (the same meridian as u = 0).
	std::vector<Vec3> dirs;
	for (float z : {-1e-3f, -1e-6f, -1e-9f, -1e-20f, -0.0f, 0.0f}) {
		dirs.push_back(glm::normalize(Vec3{1.0f, 0.3f, z}));
		dirs.push_back(glm::normalize(Vec3{1.0f, -0.7f, z}));
	}
	RNG rng(judge::secret_seed_or(72));
	for (int n = 0; n < 10000; n++) dirs.push_back(uv_to_direction(rng.unit2()));
	std::vector<Vec2> uvs = student_uvs(dirs);
	int bad = 0;
	std::string first, hint;
	for (size_t n = 0; n < dirs.size(); n++) {
		Vec2 uv = uvs[n];
		if (!(uv.x >= 0.0f && uv.x < 1.0f && uv.y >= 0.0f && uv.y <= 1.0f)) {
			if (bad++ > 0) continue;
			first = "direction_to_uv" + str(dirs[n]) + " = " + str(uv);
			// What the first bad u says: atan2 gives phi in [-pi, pi], so an unshifted phi makes u
			// negative; a shifted tiny negative phi rounds to 2 pi, u = 1.
			hint = uv.x < 0.0f  ? "u is negative: atan2(z, x) is in [-pi, pi], add 2 pi to a negative phi"
			       : uv.x >= 1.0f ? "wrap u = 1 back to 0 (a tiny negative phi plus 2 pi rounds to 2 pi)"
			                      : "v = theta / pi must lie in [0, 1]";
		}
	}
	INFO("uv must lie in [0, 1) x [0, 1] (env_light.h): " << hint << " (handout §7.1); " << bad
	                                                       << " failures, first: " << first);
	CHECK(bad == 0);
}

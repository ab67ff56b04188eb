// Task 2, handout §2.1 and §2.3: Triangle::hit (Möller–Trumbore). Hand-computed cases first, then
// the robustness cases: parallel rays, zero-area and tiny triangles, shared edges. The student's
// Triangle::hit answers in the subject, every ray of a test case in one request.
#include "rng.h"
#include "shape_check.h"
#include "student_shapes.h"

#include "lab_catch2.h"

#include <cmath>
#include <sstream>
#include <tuple>
#include <vector>

using namespace task2;
using Query = protocol::Triangle_Hits::Query;

namespace {

Triangle triangle(Vec3 p0, Vec3 p1, Vec3 p2, Vec3 n0, Vec3 n1, Vec3 n2) {
	Triangle tri;
	tri.v0 = {p0, n0};
	tri.v1 = {p1, n1};
	tri.v2 = {p2, n2};
	return tri;
}

// Flat shading: every vertex normal is the face normal (or +z for a zero-area triangle).
Triangle triangle(Vec3 p0, Vec3 p1, Vec3 p2) {
	Vec3 n = glm::cross(p1 - p0, p2 - p0);
	n = glm::length(n) > 0.0f ? glm::normalize(n) : Vec3{0.0f, 0.0f, 1.0f};
	return triangle(p0, p1, p2, n, n, n);
}

// The test triangle of this file: in the plane z = -3, with edges e1 = (4, 0, 0), e2 = (0, 4, 0),
// so the point with barycentric coordinates (u, v) is (-1 + 4u, -1 + 4v, -3). Face normal +z.
const Triangle ABC = triangle(Vec3{-1.0f, -1.0f, -3.0f}, Vec3{3.0f, -1.0f, -3.0f}, Vec3{-1.0f, 3.0f, -3.0f});

Vec3 point_of_abc(float u, float v) {
	return Vec3{-1.0f + 4.0f * u, -1.0f + 4.0f * v, -3.0f};
}

std::string describe(const Triangle& tri, const Ray& ray) {
	std::ostringstream out;
	out << "Triangle::hit for the triangle " << show(tri.v0.position) << ", " << show(tri.v1.position) << ", "
	    << show(tri.v2.position) << " and the ray " << show(ray);
	return out.str();
}

// Checks a hit against exact expected values (the tolerance is float rounding of O(1) numbers).
void check_hit(const Triangle& tri, const Ray& ray, const Trace& got, float t, Vec3 position, Vec3 normal) {
	INFO(describe(tri, ray) << ": expected a hit at t = " << t << ", position " << show(position) << ", normal "
	     << show(normal) << "; got " << (got.hit ? "a hit" : "a miss") << " at t = " << got.distance << ", position "
	     << show(got.position) << ", normal " << show(got.normal)
	     << ". t is the ray parameter: position = point + t dir, whatever the length of dir (handout §2.1)");
	REQUIRE(got.hit);
	CHECK(std::abs(got.distance - t) <= 1e-5f * t);
	CHECK(glm::length(got.position - position) <= 1e-5f);
	CHECK(glm::length(got.normal - normal) <= 1e-5f);
	CHECK(got.origin == ray.point);
}

// Returns whether it passed, so that loops can stop at the first failure.
bool check_miss(const Triangle& tri, const Ray& ray, const Trace& got, const char* why) {
	INFO(describe(tri, ray) << ": expected a miss because " << why << "; got a hit at t = " << got.distance);
	CHECK(!got.hit);
	INFO("trace.distance must never be NaN (handout §2.3)");
	CHECK(!std::isnan(got.distance));
	return !got.hit && !std::isnan(got.distance);
}

} // namespace

TEST_CASE("Triangle::hit: a ray through the interior hits at the analytic distance, position and normal", "[id:t2.triangle.interior][fn:Triangle::hit]") {
	// Straight down, and an oblique ray from (0.5, 0.25, 1) to (0.5, 0.5, -3), with dir = that
	// difference (t = 1).
	const Ray down(Vec3{0.0f}, Vec3{0.0f, 0.0f, -1.0f}), oblique(Vec3{0.5f, 0.25f, 1.0f}, Vec3{0.0f, 0.25f, -4.0f});
	std::vector<Trace> got = student_hits({{ABC, down}, {ABC, oblique}});
	check_hit(ABC, down, got[0], 3.0f, Vec3{0.0f, 0.0f, -3.0f}, Vec3{0.0f, 0.0f, 1.0f});
	check_hit(ABC, oblique, got[1], 1.0f, Vec3{0.5f, 0.5f, -3.0f}, Vec3{0.0f, 0.0f, 1.0f});
}

TEST_CASE("Triangle::hit: t is in the ray's parameter, also for non-unit directions", "[id:t2.triangle.ray-parameter][fn:Triangle::hit]") {
	const std::vector<float> scales{0.25f, 0.5f, 2.0f, 8.0f, 1000.0f};
	std::vector<Query> queries;
	for (float scale : scales) queries.push_back({ABC, Ray(Vec3{0.5f, 0.25f, 1.0f}, scale * Vec3{0.0f, 0.25f, -4.0f})});
	std::vector<Trace> got = student_hits(queries);
	for (size_t i = 0; i < scales.size(); i++) {
		float scale = scales[i];
		CAPTURE(scale);
		check_hit(ABC, queries[i].ray, got[i], 1.0f / scale, Vec3{0.5f, 0.5f, -3.0f}, Vec3{0.0f, 0.0f, 1.0f});
	}
}

TEST_CASE("Triangle::hit: both faces are hit, and the normal is not flipped towards the ray", "[id:t2.triangle.both-faces][fn:Triangle::hit]") {
	// From below the triangle (behind its face normal +z): still a hit, normal still +z (tri_mesh.h).
	const Ray up(Vec3{0.0f, 0.0f, -6.0f}, Vec3{0.0f, 0.0f, 1.0f});
	check_hit(ABC, up, student_hit(ABC, up), 3.0f, Vec3{0.0f, 0.0f, -3.0f}, Vec3{0.0f, 0.0f, 1.0f});
}

TEST_CASE("Triangle::hit: the normal interpolates the vertex normals with weights (1 - u - v, u, v)", "[id:t2.triangle.normal-interpolation][fn:Triangle::hit]") {
	Vec3 n0{0.0f, 0.0f, 1.0f}, n1{1.0f, 0.0f, 0.0f}, n2{0.0f, 1.0f, 0.0f};
	Triangle tri = triangle(ABC.v0.position, ABC.v1.position, ABC.v2.position, n0, n1, n2);
	// u = 0.125, v = 0.5: weights 0.375 (v0), 0.125 (v1), 0.5 (v2), all different.
	Ray ray(point_of_abc(0.125f, 0.5f) + Vec3{0.0f, 0.0f, 2.0f}, Vec3{0.0f, 0.0f, -1.0f});
	Vec3 expected = glm::normalize(0.375f * n0 + 0.125f * n1 + 0.5f * n2);
	Trace got = student_hit(tri, ray);
	REQUIRE(got.hit);
	std::string hint = "interpolate the vertex normals with the barycentric coordinates and normalize (handout §2.1)";
	if (glm::length(got.normal - n0) < 1e-4f) {
		hint = "that is v0.normal alone: the normal must interpolate all three vertex normals (handout §2.1)";
	} else if (std::abs(glm::length(got.normal) - 1.0f) > 1e-4f &&
	           glm::length(glm::normalize(got.normal) - expected) < 1e-4f) {
		hint = "right direction, but normalize the interpolated normal (handout §2.1)";
	} else {
		// The five wrong assignments of the weights (1 - u - v, u, v) to the vertices.
		float w[3] = {0.375f, 0.125f, 0.5f};
		int perms[5][3] = {{0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
		for (auto& p : perms) {
			if (glm::length(got.normal - glm::normalize(w[p[0]] * n0 + w[p[1]] * n1 + w[p[2]] * n2)) < 1e-4f)
				hint = "the weights are on the wrong vertices: v0 gets 1 - u - v, v1 gets u, v2 gets v, where u and v "
				       "multiply e1 = p1 - p0 and e2 = p2 - p0 (handout §2.1)";
		}
	}
	INFO("vertex normals " << show(n0) << ", " << show(n1) << ", " << show(n2) << ", hit at u = 0.125, v = 0.5: "
	     "expected the normal " << show(expected) << ", got " << show(got.normal) << ": " << hint);
	CHECK(glm::length(got.normal - expected) <= 1e-5f);
}

TEST_CASE("Triangle::hit: rays just outside each edge miss, rays just inside hit", "[id:t2.triangle.edges][fn:Triangle::hit]") {
	// 1e-3 in barycentric units (4e-3 in space here): far beyond rounding and any edge slack.
	const float d = 1e-3f;
	struct Case {
		float u, v;
		bool inside;
		const char* where;
	};
	const std::vector<Case> cases{
		{-d, 0.5f, false, "outside the edge v0-v2 (u < 0)"},    {d, 0.5f, true, "inside the edge v0-v2"},
		{0.5f, -d, false, "outside the edge v0-v1 (v < 0)"},    {0.5f, d, true, "inside the edge v0-v1"},
		{0.5f + d, 0.5f, false, "outside the edge v1-v2 (u + v > 1)"},
		{0.5f - d, 0.5f - d, true, "inside the edge v1-v2"},   {d, d, true, "inside, next to v0"},
		{1.0f - 2.0f * d, d, true, "inside, next to v1"},      {d, 1.0f - 2.0f * d, true, "inside, next to v2"},
		{1.5f, 0.2f, false, "far outside, beyond v1"},          {-0.5f, -0.5f, false, "far outside, beyond v0"},
	};
	// Each target point is approached along -z and along an oblique direction (dir (-1, -2, -3)).
	std::vector<Query> queries;
	std::vector<const Case*> of_query;
	for (Vec3 back : {Vec3{0.0f, 0.0f, 2.0f}, Vec3{1.0f, 2.0f, 3.0f}}) {
		for (const Case& c : cases) {
			Vec3 target = point_of_abc(c.u, c.v);
			queries.push_back({ABC, Ray(target + back, -back)});
			of_query.push_back(&c);
		}
	}
	std::vector<Trace> answers = student_hits(queries);
	for (size_t i = 0; i < queries.size(); i++) {
		{
			const Case& c = *of_query[i];
			const Ray& ray = queries[i].ray;
			const Trace& got = answers[i];
			INFO(describe(ABC, ray) << ": the ray crosses the plane at barycentric u = " << c.u << ", v = " << c.v
			     << ", " << c.where << ", so it must " << (c.inside ? "hit" : "miss") << "; got a "
			     << (got.hit ? "hit" : "miss") << ". Inside means u >= 0, v >= 0 and u + v <= 1 (handout §2.1)");
			CHECK(got.hit == c.inside);
			if (got.hit && c.inside) CHECK(std::abs(got.distance - 1.0f) <= 1e-5f);
		}
	}
}

TEST_CASE("Triangle::hit: triangles behind the ray's origin are missed", "[id:t2.triangle.behind][fn:Triangle::hit]") {
	const Ray away(Vec3{0.0f, 0.0f, -5.0f}, Vec3{0.0f, 0.0f, -1.0f});
	check_miss(ABC, away, student_hit(ABC, away),
	           "the plane is at t = -2, behind the origin: dist_bounds starts at 0 (handout §2.3)");
}

TEST_CASE("Triangle::hit: dist_bounds are inclusive at both ends", "[id:t2.triangle.bounds-inclusive][fn:Triangle::hit]") {
	// t = 3 exactly (integer coordinates: any formula computes it without rounding).
	Ray ray(Vec3{0.0f}, Vec3{0.0f, 0.0f, -1.0f});
	const float t = 3.0f, below = t * (1.0f - 1e-6f), above = t * (1.0f + 1e-6f);
	auto with_bounds = [](Ray r, float lo, float hi) {
		r.dist_bounds = Vec2{lo, hi};
		return r;
	};
	const char* rule = "a hit counts when dist_bounds.x <= t <= dist_bounds.y (ray.h, handout §2.3)";
	const std::vector<Ray> inside{with_bounds(ray, t, t), with_bounds(ray, below, above), with_bounds(ray, 0.0f, above),
	                              with_bounds(ray, below, INF_F)};
	const Ray too_short = with_bounds(ray, 0.0f, below), too_late = with_bounds(ray, above, INF_F);
	// The same for an oblique, non-unit ray (t = 0.5, known to ~1e-7): margins of 1e-4.
	Ray oblique(Vec3{0.5f, 0.25f, 1.0f}, Vec3{0.0f, 0.5f, -8.0f});
	const std::vector<std::tuple<Ray, bool>> oblique_cases{{with_bounds(oblique, 0.49995f, 0.50005f), true},
	                                                       {with_bounds(oblique, 0.0f, 0.49995f), false},
	                                                       {with_bounds(oblique, 0.50005f, INF_F), false}};
	std::vector<Query> queries;
	for (const Ray& r : inside) queries.push_back({ABC, r});
	queries.push_back({ABC, too_short});
	queries.push_back({ABC, too_late});
	for (const auto& [r, in] : oblique_cases) queries.push_back({ABC, r});
	std::vector<Trace> got = student_hits(queries);

	for (size_t i = 0; i < inside.size(); i++) {
		INFO(describe(ABC, inside[i]) << ": the hit at t = 3 is inside the bounds and must count; " << rule);
		CHECK(got[i].hit);
	}
	check_miss(ABC, too_short, got[inside.size()], "the hit at t = 3 is just beyond dist_bounds.y (handout §2.3)");
	check_miss(ABC, too_late, got[inside.size() + 1], "the hit at t = 3 is just before dist_bounds.x (handout §2.3)");
	for (size_t i = 0; i < oblique_cases.size(); i++) {
		const auto& [r, in] = oblique_cases[i];
		INFO(describe(ABC, r) << ": the hit at t = 0.5 is " << (in ? "inside" : "outside") << " the bounds; " << rule);
		CHECK(got[inside.size() + 2 + i].hit == in);
	}
}

TEST_CASE("Triangle::hit: rays parallel to the triangle never hit and never give NaN", "[id:t2.triangle.parallel][fn:Triangle::hit]") {
	// A tilted triangle (plane x + y + z = 1) and a ray along its edge v0-v1, and the test triangle
	// with rays in and parallel to its plane.
	Triangle tilted = triangle(Vec3{1.0f, 0.0f, 0.0f}, Vec3{0.0f, 1.0f, 0.0f}, Vec3{0.0f, 0.0f, 1.0f});
	const std::vector<std::tuple<Triangle, Ray, const char*>> cases{
		{ABC, Ray(Vec3{-5.0f, 0.0f, -3.0f}, Vec3{1.0f, 0.0f, 0.0f}), "the ray lies in the triangle's plane (det = 0, handout §2.3)"},
		{ABC, Ray(Vec3{-5.0f, -5.0f, -3.0f}, Vec3{1.0f, 1.0f, 0.0f}), "the ray lies in the triangle's plane (det = 0, handout §2.3)"},
		{ABC, Ray(Vec3{-5.0f, 0.0f, -2.0f}, Vec3{1.0f, 0.0f, 0.0f}),
		 "the ray runs parallel to the triangle's plane (det = 0, handout §2.3)"},
		{tilted, Ray(Vec3{2.0f, -1.0f, 0.0f}, Vec3{-1.0f, 1.0f, 0.0f}),
		 "the ray runs along an edge, inside the plane (det = 0, handout §2.3)"},
	};
	std::vector<Query> queries;
	for (const auto& [tri, ray, why] : cases) queries.push_back({tri, ray});
	std::vector<Trace> got = student_hits(queries);
	for (size_t i = 0; i < cases.size(); i++) {
		const auto& [tri, ray, why] = cases[i];
		check_miss(tri, ray, got[i], why);
	}
}

TEST_CASE("Triangle::hit: zero-area triangles never hit, even rays through their points", "[id:t2.triangle.zero-area][fn:Triangle::hit]") {
	struct Degenerate {
		Vec3 p0, p1, p2;
		const char* what;
	};
	// Integer coordinates, so the edges are exactly parallel (or zero) in float too.
	const std::vector<Degenerate> triangles{
		{{-1, -1, -3}, {1, 1, -3}, {3, 3, -3}, "collinear vertices"},
		{{1, 2, 3}, {2, 4, 6}, {4, 8, 12}, "collinear vertices"},
		{{3, 3, -3}, {-1, -1, -3}, {1, 1, -3}, "collinear vertices"},
		{{0, 0, -3}, {0, 0, -3}, {2, 1, -3}, "v0 == v1"},
		{{0, 0, -3}, {2, 1, -3}, {2, 1, -3}, "v1 == v2"},
		{{2, 1, -3}, {0, 0, -3}, {2, 1, -3}, "v0 == v2"},
		{{1, 1, -3}, {1, 1, -3}, {1, 1, -3}, "three equal vertices"},
	};
	// Aim at each vertex and at points along each side, from several directions.
	std::vector<Query> queries;
	std::vector<const Degenerate*> of_query;
	for (const Degenerate& d : triangles) {
		Triangle tri = triangle(d.p0, d.p1, d.p2);
		std::vector<Vec3> targets{d.p0, d.p1, d.p2, 0.5f * (d.p0 + d.p1), 0.5f * (d.p1 + d.p2),
		                          0.25f * d.p0 + 0.75f * d.p2};
		for (Vec3 target : targets) {
			for (Vec3 back : {Vec3{0.0f, 0.0f, 2.0f}, Vec3{1.0f, -2.0f, 3.0f}, Vec3{-0.5f, 0.25f, -4.0f}}) {
				queries.push_back({tri, Ray(target + back, -back)});
				of_query.push_back(&d);
			}
		}
	}
	std::vector<Trace> got = student_hits(queries);
	for (size_t i = 0; i < queries.size(); i++) {
		std::string why = std::string(of_query[i]->what) + ": a triangle with zero area has nothing to hit; its det is "
		                  "0 (handout §2.3)";
		if (!check_miss(queries[i].triangle, queries[i].ray, got[i], why.c_str())) return;
	}
}

TEST_CASE("Triangle::hit: tiny triangles are hit (no fixed epsilon on det)", "[id:t2.triangle.tiny][fn:Triangle::hit]") {
	// det = d . (e1 x e2) scales with the square of the size: 1e-10 for edges of 1e-5.
	const std::vector<float> sizes{1e-3f, 1e-5f, 1e-8f, 1e-12f};
	std::vector<Query> queries;
	for (float size : sizes) {
		queries.push_back({triangle(Vec3{0.0f, 0.0f, -1.0f}, Vec3{size, 0.0f, -1.0f}, Vec3{0.0f, size, -1.0f}),
		                   Ray(Vec3{0.25f * size, 0.25f * size, 0.0f}, Vec3{0.0f, 0.0f, -1.0f})});
	}
	std::vector<Trace> answers = student_hits(queries);
	for (size_t i = 0; i < sizes.size(); i++) {
		const Trace& got = answers[i];
		INFO(describe(queries[i].triangle, queries[i].ray) << ": a triangle with edges of " << sizes[i] << " must be hit "
		     "like any other. Do not reject |det| < some epsilon: det scales with the triangle's area; only det == 0 "
		     "means no hit (handout §2.3)");
		REQUIRE(got.hit);
		CHECK(std::abs(got.distance - 1.0f) <= 1e-5f);
		CHECK(glm::length(got.normal - Vec3{0.0f, 0.0f, 1.0f}) <= 1e-5f);
	}
}

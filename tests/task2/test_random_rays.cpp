// Task 2, handout §2.1-§2.4: Triangle::hit and Sphere::hit against the exact answer on 10^5 random
// rays each, and against NaN on extreme inputs. The student's answers come from the subject, all the
// rays of a test case in one request.
//
// A ray counts as wrong only when the exact answer, solved in double, is sure within the bound of
// what float rounding can do to a correct implementation (shape_check.h): rays within that bound of
// an edge, the silhouette or an end of dist_bounds, within the allowed edge slack of 1e-4, or too
// nearly parallel to a triangle for the sign of its determinant, may go either way: about 0.05 % of
// the rays here. Distances and normals are compared within the same bound.
#include "judge.h"
#include "rng.h"
#include "shape_check.h"
#include "student_shapes.h"

#include "lab_catch2.h"

#include <cmath>
#include <sstream>

using namespace task2;

namespace {

constexpr int RAYS = 100000;

float log_uniform(RNG& rng, float lo_exp, float hi_exp) {
	return std::pow(10.0f, lo_exp + (hi_exp - lo_exp) * rng.unit());
}

Vec3 in_cube(RNG& rng, float half) {
	return half * Vec3{2.0f * rng.unit() - 1.0f, 2.0f * rng.unit() - 1.0f, 2.0f * rng.unit() - 1.0f};
}

Vec3 random_unit(RNG& rng) {
	float z = 1.0f - 2.0f * rng.unit(), phi = 2.0f * PI_F * rng.unit();
	float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
	return Vec3{r * std::cos(phi), r * std::sin(phi), z};
}

// A third of the rays keep [0, inf); the others get bounds that cut the hit on either side.
Vec2 random_bounds(RNG& rng, float scale) {
	switch (rng.integer(3)) {
	case 0: return Vec2{0.0f, INF_F};
	case 1: return Vec2{scale * rng.unit(), INF_F};
	default: {
		float lo = scale * rng.unit();
		return Vec2{lo, lo + scale * rng.unit()};
	}
	}
}

struct Tally {
	size_t wrong = 0, either = 0, hits = 0;
	std::string first;

	// describe_shape(): the shape in words, asked for only for the first wrong answer.
	template<class Describe>
	void add(const Expectation& e, const Trace& got, const Ray& ray, Describe describe_shape, const char* section) {
		either += e.verdict == Verdict::either;
		hits += got.hit;
		std::string problem = hit_problem(e, got, ray, section);
		if (problem.empty() || wrong++ > 0) return;
		std::ostringstream out;
		out << describe_shape() << ", ray " << show(ray) << ": " << problem;
		first = out.str();
	}
};

// A triangle near the origin at a random scale, its vertex normals within ~35 degrees of the face
// normal (so that the interpolated normal never vanishes).
Triangle random_triangle(RNG& rng, float scale) {
	Triangle tri;
	Vec3 p[3] = {scale * in_cube(rng, 1.0f), scale * in_cube(rng, 1.0f), scale * in_cube(rng, 1.0f)};
	Vec3 face = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
	Tri_Mesh_Vert* v[3] = {&tri.v0, &tri.v1, &tri.v2};
	for (int i = 0; i < 3; i++) *v[i] = {p[i], glm::normalize(face + 0.7f * in_cube(rng, 1.0f) / std::sqrt(3.0f))};
	return tri;
}

} // namespace

TEST_CASE("Triangle::hit agrees with the exact answer on 10^5 random rays", "[id:t2.triangle.random-rays][fn:Triangle::hit]") {
	// Origins within 10 sizes of the triangle, aimed at points around it (half of them inside),
	// |dir| from 0.01 to 100, coordinates at scales from 1e-3 to 1e3.
	RNG rng(judge::secret_seed_or(1234));
	std::vector<protocol::Triangle_Hits::Query> queries;
	for (int i = 0; i < RAYS; i++) {
		float scale = log_uniform(rng, -3.0f, 3.0f);
		Triangle tri = random_triangle(rng, scale);
		if (glm::length(glm::cross(tri.v1.position - tri.v0.position, tri.v2.position - tri.v0.position)) <
		    1e-3f * scale * scale) {
			i--; // a needle: fine, but the zero-area test case covers degenerate shapes
			continue;
		}
		// Half the targets inside the triangle, half anywhere in a box around it (u, v in [-0.25, 1.25]).
		float u = 1.5f * rng.unit() - 0.25f, v = 1.5f * rng.unit() - 0.25f;
		if (rng.coin_flip(0.5f)) {
			float root = std::sqrt(rng.unit());
			u = root * (1.0f - rng.unit()), v = root - u; // uniform over the triangle: u, v >= 0, u + v <= 1
		}
		Vec3 e1 = tri.v1.position - tri.v0.position, e2 = tri.v2.position - tri.v0.position;
		Vec3 target = tri.v0.position + u * e1 + v * e2;
		Vec3 origin = scale * in_cube(rng, 10.0f);
		Vec3 dir = (target - origin) / glm::length(target - origin) * log_uniform(rng, -2.0f, 2.0f);
		queries.push_back({tri, Ray(origin, dir, random_bounds(rng, 2.0f * glm::length(target - origin) / glm::length(dir)))});
	}
	std::vector<Trace> got = student_hits(queries);
	Tally tally;
	for (size_t i = 0; i < queries.size(); i++) {
		const auto& [tri, ray] = queries[i];
		auto shape = [&tri = tri] { // (C++17 lambdas capture a structured binding only this way)
			return "triangle " + show(tri.v0.position) + ", " + show(tri.v1.position) + ", " + show(tri.v2.position);
		};
		tally.add(expect_hit(tri, ray), got[i], ray, shape, "handout §2.1");
	}
	INFO(tally.wrong << " of " << RAYS << " rays got a wrong answer (" << tally.either << " rays within rounding of an "
	     "edge or bound were accepted either way; " << tally.hits << " hits). First: " << tally.first);
	CHECK(tally.wrong == 0);
	INFO("Triangle::hit found only " << tally.hits << " hits in " << RAYS << " rays, although about half of them are "
	     "aimed inside the triangle (handout §2.1)");
	CHECK(tally.hits > RAYS / 5);
}

TEST_CASE("Sphere::hit agrees with the exact answer on 10^5 random rays", "[id:t2.sphere.random-rays][fn:Sphere::hit]") {
	// Radii from 0.01 to 100; origins from 0.2 r (inside) to 30 r away, aimed at points within
	// 1.3 r of the centre (most hit, some pass by); |dir| from 0.01 to 100.
	RNG rng(judge::secret_seed_or(5678));
	std::vector<protocol::Sphere_Hits::Query> queries;
	for (int i = 0; i < RAYS; i++) {
		Sphere sphere{log_uniform(rng, -2.0f, 2.0f)};
		float r = sphere.radius;
		Vec3 origin = r * log_uniform(rng, std::log10(0.2f), std::log10(30.0f)) * random_unit(rng);
		Vec3 target = 1.3f * r * std::cbrt(rng.unit()) * random_unit(rng);
		Vec3 dir = glm::normalize(target - origin) * log_uniform(rng, -2.0f, 2.0f);
		queries.push_back({sphere, Ray(origin, dir, random_bounds(rng, 2.0f * (glm::length(origin) + r) / glm::length(dir)))});
	}
	std::vector<Trace> got = student_hits(queries);
	Tally tally;
	for (size_t i = 0; i < queries.size(); i++) {
		const auto& [sphere, ray] = queries[i];
		auto shape = [&sphere = sphere] {
			std::ostringstream out;
			out.precision(9);
			out << "sphere of radius " << sphere.radius;
			return out.str();
		};
		tally.add(expect_hit(sphere, ray), got[i], ray, shape, "handout §2.2");
	}
	INFO(tally.wrong << " of " << RAYS << " rays got a wrong answer (" << tally.either << " rays within rounding of "
	     "the silhouette or a bound were accepted either way; " << tally.hits << " hits). First: " << tally.first);
	CHECK(tally.wrong == 0);
	INFO("Sphere::hit found only " << tally.hits << " hits in " << RAYS << " rays, although most of them are aimed "
	     "inside the sphere (handout §2.2)");
	CHECK(tally.hits > RAYS / 5);
}

TEST_CASE("Triangle::hit and Sphere::hit never return NaN, whatever finite input they get", "[id:t2.shapes.no-nan][fn:Triangle::hit][fn:Sphere::hit]") {
	// Every coordinate and bound drawn with random sign and magnitude 10^-30 ... 10^30, some exactly
	// 0; radii 0 or 10^-15 ... 10^15 (so that r^2 is still a normal float). Products overflow and
	// underflow; the answer may be a hit or a miss, but a hit needs a finite distance inside
	// dist_bounds, a position and normal without NaN, and a miss never has a NaN distance. (Write
	// accept tests positively so NaN fails them, handout §2.3.) One exception: a sphere of radius 0,
	// or one so small against its distance (|o| / r > ~1e7) that the float hit point lands on its
	// centre, has no normal; such hits are not checked for a NaN normal.
	RNG rng(judge::secret_seed_or(31337));
	auto extreme = [&](float max_exponent = 30.0f) {
		if (rng.integer(10) == 0) return 0.0f;
		return (rng.coin_flip(0.5f) ? -1.0f : 1.0f) * log_uniform(rng, -max_exponent, max_exponent);
	};
	auto extreme_vec = [&]() { return Vec3{extreme(), extreme(), extreme()}; };
	// Component by component: a far hit may lie at +inf on one axis and -inf on another (its
	// distance finite, the product t d overflowing), whose sum would be NaN.
	auto has_nan = [](Vec3 v) { return std::isnan(v.x) || std::isnan(v.y) || std::isnan(v.z); };
	auto problem_of = [&](const Trace& got, const Ray& ray, bool normal_exists) -> std::string {
		if (std::isnan(got.distance)) return "trace.distance is NaN";
		if (!got.hit) return "";
		if (!(std::isfinite(got.distance) && got.distance >= ray.dist_bounds.x && got.distance <= ray.dist_bounds.y))
			return "a hit with a distance that is infinite or outside dist_bounds";
		if (has_nan(got.position)) return "a hit with a NaN position";
		if (normal_exists && has_nan(got.normal)) return "a hit with a NaN normal";
		return "";
	};
	std::vector<protocol::Triangle_Hits::Query> triangle_queries;
	std::vector<protocol::Sphere_Hits::Query> sphere_queries;
	for (int i = 0; i < RAYS; i++) {
		Ray ray(extreme_vec(), extreme_vec());
		if (rng.coin_flip(0.5f)) {
			float a = std::abs(extreme()), b = std::abs(extreme());
			ray.dist_bounds = Vec2{std::min(a, b), std::max(a, b)};
		}
		Triangle tri;
		Vec3 n = glm::normalize(Vec3{1.0f, 2.0f, 3.0f});
		tri.v0 = {extreme_vec(), n};
		tri.v1 = {extreme_vec(), n};
		tri.v2 = {extreme_vec(), n};
		triangle_queries.push_back({tri, ray});
		sphere_queries.push_back({Sphere{std::abs(extreme(15.0f))}, ray});
	}
	std::vector<Trace> triangle_hits = student_hits(triangle_queries), sphere_hits = student_hits(sphere_queries);
	size_t bad = 0;
	std::string first;
	for (int i = 0; i < RAYS; i++) {
		const Ray& ray = triangle_queries[i].ray;
		const Triangle& tri = triangle_queries[i].triangle;
		const Sphere& sphere = sphere_queries[i].sphere;
		const Trace& sphere_hit = sphere_hits[i];
		bool off_centre = sphere.radius > 0.0f && glm::length(DVec3(sphere_hit.position)) >= 0.5 * sphere.radius;
		std::string tri_problem = problem_of(triangle_hits[i], ray, true);
		std::string sphere_problem = problem_of(sphere_hit, ray, off_centre);
		if (tri_problem.empty() && sphere_problem.empty()) continue;
		if (bad++ > 0) continue;
		std::ostringstream out;
		out.precision(9);
		if (!tri_problem.empty())
			out << "Triangle::hit: " << tri_problem << " for the triangle " << show(tri.v0.position) << ", "
			    << show(tri.v1.position) << ", " << show(tri.v2.position);
		else
			out << "Sphere::hit: " << sphere_problem << " for radius " << sphere.radius;
		out << " and the ray " << show(ray);
		first = out.str();
	}
	INFO(bad << " of " << RAYS << " extreme inputs gave NaN or an invalid hit. First: " << first
	     << " (handout §2.3)");
	CHECK(bad == 0);
}

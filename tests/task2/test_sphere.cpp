// Task 2, handout §2.2 and §2.3: Sphere::hit in the sphere's local space (centre at the origin),
// for rays whose direction may have any length. The student's Sphere::hit answers in the subject,
// every ray of a test case in one request.
#include "judge.h"
#include "rng.h"
#include "shape_check.h"
#include "student_shapes.h"

#include "lab_catch2.h"

#include <cmath>
#include <functional>
#include <sstream>

using namespace task2;
using Query = protocol::Sphere_Hits::Query;

namespace {

// The expected answers of one test case: each ray with its check, asked in one request and checked
// in order.
class Sphere_Checks {
public:
	// A hit at exactly t (the tolerance is float rounding of O(1) numbers) with the given normal.
	void hit(const Sphere& sphere, const Ray& ray, float t, Vec3 normal, const std::string& why) {
		add(sphere, ray, [=](const Trace& got) {
			Vec3 position = ray.point + t * ray.dir;
			INFO(describe(sphere, ray) << ": expected a hit at t = " << t << " (" << why << "), position "
			     << show(position) << ", outward normal " << show(normal) << "; got " << (got.hit ? "a hit" : "a miss")
			     << " at t = " << got.distance << ", position " << show(got.position) << ", normal "
			     << show(got.normal) << " (handout §2.2)");
			REQUIRE(got.hit);
			CHECK(std::abs(got.distance - t) <= 1e-5f * t);
			CHECK(glm::length(got.position - position) <= 1e-5f * glm::length(position));
			CHECK(glm::length(got.normal - normal) <= 1e-5f);
			CHECK(got.origin == ray.point);
		});
	}
	void miss(const Sphere& sphere, const Ray& ray, const std::string& why) {
		add(sphere, ray, [=](const Trace& got) {
			INFO(describe(sphere, ray) << ": expected a miss because " << why << "; got a hit at t = " << got.distance);
			CHECK(!got.hit);
			INFO("trace.distance must never be NaN (handout §2.3)");
			CHECK(!std::isnan(got.distance));
		});
	}
	void run() const {
		std::vector<Trace> got = student_hits(queries);
		for (size_t i = 0; i < checks.size(); i++) checks[i](got[i]);
	}

private:
	static std::string describe(const Sphere& sphere, const Ray& ray) {
		std::ostringstream out;
		out.precision(9);
		out << "Sphere::hit for radius " << sphere.radius << " and the ray " << show(ray);
		return out.str();
	}
	void add(const Sphere& sphere, const Ray& ray, std::function<void(const Trace&)> check) {
		queries.push_back({sphere, ray});
		checks.push_back(std::move(check));
	}
	std::vector<Query> queries;
	std::vector<std::function<void(const Trace&)>> checks;
};

Ray bounded(Ray ray, float lo, float hi) {
	ray.dist_bounds = Vec2{lo, hi};
	return ray;
}

const Sphere R2{2.0f};
const Vec3 DOWN{0.0f, 0.0f, -1.0f};

} // namespace

TEST_CASE("Sphere::hit: a ray from outside hits the near root, with the outward unit normal", "[id:t2.sphere.outside][fn:Sphere::hit]") {
	Sphere_Checks checks;
	checks.hit(R2, Ray(Vec3{0.0f, 0.0f, 10.0f}, DOWN), 8.0f, Vec3{0.0f, 0.0f, 1.0f}, "roots 8 and 12");
	float t = 10.0f - std::sqrt(3.0f); // enters at (1, 0, sqrt 3)
	checks.hit(R2, Ray(Vec3{1.0f, 0.0f, 10.0f}, DOWN), t, Vec3{0.5f, 0.0f, 0.5f * std::sqrt(3.0f)},
	          "enters at (1, 0, sqrt 3)");
	checks.hit(R2, Ray(Vec3{-6.0f, 8.0f, 0.0f}, Vec3{0.6f, -0.8f, 0.0f}), 8.0f, Vec3{-0.6f, 0.8f, 0.0f},
	          "from distance 10 towards the centre");
	checks.run();
}

TEST_CASE("Sphere::hit: t is in the ray's parameter, also for non-unit directions", "[id:t2.sphere.ray-parameter][fn:Sphere::hit]") {
	Sphere_Checks checks;
	for (float scale : {0.5f, 0.25f, 3.0f, 4.0f, 1000.0f}) {
		Ray ray(Vec3{0.0f, 0.0f, 10.0f}, scale * DOWN);
		std::ostringstream why;
		why << "|dir| = " << scale << ": the surface is 8 units away, which is t = 8 / |dir|; do not assume a unit "
		    << "direction: a = dir . dir";
		checks.hit(R2, ray, 8.0f / scale, Vec3{0.0f, 0.0f, 1.0f}, why.str());
	}
	checks.hit(R2, Ray(Vec3{1.0f, 0.0f, 10.0f}, 3.0f * DOWN), (10.0f - std::sqrt(3.0f)) / 3.0f,
	          Vec3{0.5f, 0.0f, 0.5f * std::sqrt(3.0f)}, "|dir| = 3, off-axis");
	checks.run();
}

TEST_CASE("Sphere::hit: a ray starting inside the sphere hits the far root", "[id:t2.sphere.inside][fn:Sphere::hit]") {
	Sphere_Checks checks;
	checks.hit(R2, Ray(Vec3{0.0f, 0.0f, 0.5f}, Vec3{0.0f, 0.0f, 1.0f}), 1.5f, Vec3{0.0f, 0.0f, 1.0f},
	          "the near root is -2.5, behind the origin");
	checks.hit(R2, Ray(Vec3{0.0f}, Vec3{3.0f, 4.0f, 0.0f}), 0.4f, Vec3{0.6f, 0.8f, 0.0f},
	          "from the centre with |dir| = 5; the normal points outwards, away from the centre");
	checks.run();
}

TEST_CASE("Sphere::hit: the far root counts when the near one is outside dist_bounds", "[id:t2.sphere.far-root][fn:Sphere::hit]") {
	Sphere_Checks checks;
	Ray ray(Vec3{0.0f, 0.0f, 10.0f}, DOWN); // roots 8 and 12
	checks.hit(R2, bounded(ray, 9.0f, INF_F), 12.0f, Vec3{0.0f, 0.0f, -1.0f},
	          "the near root 8 is below dist_bounds.x = 9; the far root 12 is the first hit in the bounds");
	checks.miss(R2, bounded(ray, 8.5f, 11.0f),
	           "both roots, 8 and 12, are outside dist_bounds [8.5, 11] (handout §2.3)");
	checks.run();
}

TEST_CASE("Sphere::hit: spheres behind the ray, and rays passing beside them, miss", "[id:t2.sphere.miss][fn:Sphere::hit]") {
	Sphere_Checks checks;
	checks.miss(R2, Ray(Vec3{0.0f, 0.0f, 10.0f}, Vec3{0.0f, 0.0f, 1.0f}), "both roots (-8 and -12) are negative");
	checks.miss(R2, Ray(Vec3{2.5f, 0.0f, 10.0f}, DOWN), "the ray passes 2.5 from the centre of a sphere of radius 2");
	checks.miss(R2, Ray(Vec3{0.0f, 2.02f, 10.0f}, 7.0f * DOWN), "the ray passes 2.02 from the centre (|dir| = 7)");
	checks.run();
}

TEST_CASE("Sphere::hit: dist_bounds are inclusive at both ends, for both roots", "[id:t2.sphere.bounds-inclusive][fn:Sphere::hit]") {
	Sphere_Checks checks;
	// Roots exactly 8 and 12 (every formula computes them without rounding here).
	Ray ray(Vec3{0.0f, 0.0f, 10.0f}, DOWN);
	const float e = 1e-6f;
	const Vec3 front{0.0f, 0.0f, 1.0f}, back{0.0f, 0.0f, -1.0f};
	checks.hit(R2, bounded(ray, 8.0f, 8.0f), 8.0f, front, "dist_bounds = [8, 8]; the bounds are inclusive");
	checks.hit(R2, bounded(ray, 8.0f * (1 - e), INF_F), 8.0f, front, "the near root 8 is just above dist_bounds.x");
	checks.hit(R2, bounded(ray, 0.0f, 8.0f * (1 + e)), 8.0f, front, "the near root 8 is just below dist_bounds.y");
	checks.hit(R2, bounded(ray, 8.0f * (1 + e), INF_F), 12.0f, back, "the near root 8 is just below dist_bounds.x");
	checks.miss(R2, bounded(ray, 0.0f, 8.0f * (1 - e)), "the near root 8 is just beyond dist_bounds.y (handout §2.3)");
	checks.hit(R2, bounded(ray, 12.0f, 12.0f), 12.0f, back, "dist_bounds = [12, 12]; the bounds are inclusive");
	checks.hit(R2, bounded(ray, 9.0f, 12.0f * (1 + e)), 12.0f, back, "the far root 12 is just below dist_bounds.y");
	checks.miss(R2, bounded(ray, 9.0f, 12.0f * (1 - e)), "the far root 12 is just beyond dist_bounds.y (handout §2.3)");
	checks.miss(R2, bounded(ray, 12.0f * (1 + e), INF_F), "both roots are below dist_bounds.x (handout §2.3)");
	checks.run();
}

TEST_CASE("Sphere::hit: tangent and nearly tangent rays give no NaN", "[id:t2.sphere.tangent][fn:Sphere::hit]") {
	// Lines at distance r (1 +- 2^-k) from the centre: hit or miss may go either way within rounding,
	// but a hit must be a proper one (shape_check.h: the tolerance grows at tangency with the spread
	// of the reference's answers for rays moved by rounding).
	RNG rng(judge::secret_seed_or(99));
	std::vector<Query> queries;
	std::vector<float> distances;
	for (int k = 8; k <= 30; k++) {
		for (float sign : {-1.0f, 0.0f, 1.0f}) {
			for (float scale : {1.0f, 0.01f, 50.0f}) {
				float r = 0.5f + 4.0f * rng.unit();
				float l = r * (1.0f + sign * std::ldexp(1.0f, -k));
				// The line x = l, y = 0, travelling along -z (rotated for variety), from z = 3r.
				float angle = 2.0f * PI_F * rng.unit();
				Vec3 side{std::cos(angle), std::sin(angle), 0.0f};
				queries.push_back({Sphere{r}, Ray(l * side + Vec3{0.0f, 0.0f, 3.0f * r}, scale * DOWN)});
				distances.push_back(l);
			}
		}
	}
	std::vector<Trace> got = student_hits(queries);
	for (size_t i = 0; i < queries.size(); i++) {
		const auto& [sphere, ray] = queries[i];
		std::string problem = hit_problem(expect_hit(sphere, ray), got[i], ray, "handout §2.2");
		INFO("Sphere::hit for radius " << sphere.radius << " and the ray " << show(ray) << " (a ray at distance "
		     << distances[i] << " from the centre): " << problem
		     << ". Clamp nothing: a negative discriminant is a miss, zero is a (tangent) hit (handout §2.3)");
		CHECK(problem.empty());
		if (!problem.empty()) return;
	}
}

TEST_CASE("Sphere::hit: small and distant spheres are hit accurately (numerically stable quadratic)", "[id:t2.sphere.stable-quadratic][fn:Sphere::hit]") {
	// A sphere of radius r seen from distance D, rays aimed within 0.9 r of the centre: all must hit,
	// with t within 1e-5 (relative) of the exact root (shape_check.h, solved in double). These rays
	// are well conditioned (they meet the sphere at least 25 degrees from grazing), so the stable
	// form of handout §2.2 is within a few eps (< 1e-6) of it; b^2 - ac cancels catastrophically when
	// r / D is small: at r / D = 1e-4 two thirds of these rays miss and t is off by up to 5e-4.
	// r / D stays >= 1e-5: the distance l from the centre to the ray's line, which decides hit or
	// miss, is known in float only to a few eps |o| (o - (b / a) d cancels; so does o x d), 0.1 r
	// at r / D = 1e-5 for 16 eps (shape_check.h). At 1e-6 that is r itself, and whether a ray aimed
	// at 0.9 r hits would depend on the grouping of the formula, not on its correctness.
	struct Config {
		float r, D;
	};
	RNG rng(judge::secret_seed_or(2718));
	for (Config c : {Config{1.0f, 1e4f}, Config{1e-3f, 1e2f}, Config{1e-2f, 1e2f}, Config{1e4f, 2e4f}}) {
		Sphere sphere{c.r};
		std::vector<Query> queries;
		for (int i = 0; i < 10000; i++) {
			Vec3 from = c.D * glm::normalize(Vec3{rng.unit() - 0.5f, rng.unit() - 0.5f, rng.unit() - 0.5f});
			// A target in the disc of radius 0.9 r through the centre, perpendicular to the view.
			Vec3 a = glm::normalize(glm::cross(from, Vec3{0.3f, 1.0f, 0.1f})), b = glm::normalize(glm::cross(from, a));
			float rho = 0.9f * c.r * std::sqrt(rng.unit()), phi = 2.0f * PI_F * rng.unit();
			Vec3 target = rho * std::cos(phi) * a + rho * std::sin(phi) * b;
			queries.push_back({sphere, Ray(from, (target - from) * (0.5f + rng.unit()))});
		}
		std::vector<Trace> got = student_hits(queries);
		size_t misses = 0, inaccurate = 0, setup_errors = 0;
		double worst = 0.0;
		std::string example;
		for (size_t i = 0; i < queries.size(); i++) {
			const Ray& ray = queries[i].ray;
			double exact = exact_near_root(sphere, ray);
			if (!(exact > 0.0)) {
				setup_errors++; // cannot happen: every ray aims inside the sphere
				continue;
			}
			if (!got[i].hit) {
				if (misses++ == 0) example = show(ray);
				continue;
			}
			double error = std::abs(double(got[i].distance) - exact) / exact;
			worst = std::max(worst, error);
			if (!(error < 1e-5) && inaccurate++ == 0) example = show(ray);
		}
		INFO("radius " << c.r << " seen from distance " << c.D << ": " << misses << " of 10000 rays aimed inside the "
		     "sphere missed it, " << inaccurate << " hits had a relative error of t above 1e-5 (worst " << worst
		     << "). Use the numerically stable discriminant and roots of handout §2.2. First bad ray: " << example);
		CHECK(misses == 0);
		CHECK(inaccurate == 0);
		REQUIRE(setup_errors == 0); // the grader's own rays all aim inside the sphere
	}
}

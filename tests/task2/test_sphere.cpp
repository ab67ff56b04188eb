// Task 2, handout §2.2 and §2.3: Sphere::hit in the sphere's local space (centre at the origin),
// for rays whose direction may have any length.
#include "rng.h"
#include "shape_oracle.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

using namespace shape_oracle;

namespace {

std::string describe(const Sphere& sphere, const Ray& ray) {
	std::ostringstream out;
	out.precision(9);
	out << "Sphere::hit for radius " << sphere.radius << " and the ray " << show(ray);
	return out.str();
}

Ray bounded(Ray ray, float lo, float hi) {
	ray.dist_bounds = Vec2{lo, hi};
	return ray;
}

// Checks a hit against exact expected values (the tolerance is float rounding of O(1) numbers).
void check_hit(const Sphere& sphere, const Ray& ray, float t, Vec3 normal, const char* why) {
	Trace got = sphere.hit(ray);
	Vec3 position = ray.point + t * ray.dir;
	INFO(describe(sphere, ray) << ": expected a hit at t = " << t << " (" << why << "), position " << show(position)
	     << ", outward normal " << show(normal) << "; got " << (got.hit ? "a hit" : "a miss") << " at t = "
	     << got.distance << ", position " << show(got.position) << ", normal " << show(got.normal)
	     << " (handout §2.2)");
	REQUIRE(got.hit);
	CHECK(std::abs(got.distance - t) <= 1e-5f * t);
	CHECK(glm::length(got.position - position) <= 1e-5f * glm::length(position));
	CHECK(glm::length(got.normal - normal) <= 1e-5f);
	CHECK(got.origin == ray.point);
}

void check_miss(const Sphere& sphere, const Ray& ray, const char* why) {
	Trace got = sphere.hit(ray);
	INFO(describe(sphere, ray) << ": expected a miss because " << why << "; got a hit at t = " << got.distance);
	CHECK(!got.hit);
	INFO("trace.distance must never be NaN (handout §2.3)");
	CHECK(!std::isnan(got.distance));
}

const Sphere R2{2.0f};
const Vec3 DOWN{0.0f, 0.0f, -1.0f};

} // namespace

TEST_CASE("Sphere::hit: a ray from outside hits the near root, with the outward unit normal") {
	check_hit(R2, Ray(Vec3{0.0f, 0.0f, 10.0f}, DOWN), 8.0f, Vec3{0.0f, 0.0f, 1.0f}, "roots 8 and 12");
	float t = 10.0f - std::sqrt(3.0f); // enters at (1, 0, sqrt 3)
	check_hit(R2, Ray(Vec3{1.0f, 0.0f, 10.0f}, DOWN), t, Vec3{0.5f, 0.0f, 0.5f * std::sqrt(3.0f)},
	          "enters at (1, 0, sqrt 3)");
	check_hit(R2, Ray(Vec3{-6.0f, 8.0f, 0.0f}, Vec3{0.6f, -0.8f, 0.0f}), 8.0f, Vec3{-0.6f, 0.8f, 0.0f},
	          "from distance 10 towards the centre");
}

TEST_CASE("Sphere::hit: t is in the ray's parameter, also for non-unit directions") {
	for (float scale : {0.5f, 0.25f, 3.0f, 4.0f, 1000.0f}) {
		Ray ray(Vec3{0.0f, 0.0f, 10.0f}, scale * DOWN);
		std::ostringstream why;
		why << "|dir| = " << scale << ": the surface is 8 units away, which is t = 8 / |dir|; do not assume a unit "
		    << "direction: a = dir . dir";
		check_hit(R2, ray, 8.0f / scale, Vec3{0.0f, 0.0f, 1.0f}, why.str().c_str());
	}
	check_hit(R2, Ray(Vec3{1.0f, 0.0f, 10.0f}, 3.0f * DOWN), (10.0f - std::sqrt(3.0f)) / 3.0f,
	          Vec3{0.5f, 0.0f, 0.5f * std::sqrt(3.0f)}, "|dir| = 3, off-axis");
}

TEST_CASE("Sphere::hit: a ray starting inside the sphere hits the far root") {
	check_hit(R2, Ray(Vec3{0.0f, 0.0f, 0.5f}, Vec3{0.0f, 0.0f, 1.0f}), 1.5f, Vec3{0.0f, 0.0f, 1.0f},
	          "the near root is -2.5, behind the origin");
	check_hit(R2, Ray(Vec3{0.0f}, Vec3{3.0f, 4.0f, 0.0f}), 0.4f, Vec3{0.6f, 0.8f, 0.0f},
	          "from the centre with |dir| = 5; the normal points outwards, away from the centre");
}

TEST_CASE("Sphere::hit: the far root counts when the near one is outside dist_bounds") {
	Ray ray(Vec3{0.0f, 0.0f, 10.0f}, DOWN); // roots 8 and 12
	check_hit(R2, bounded(ray, 9.0f, INF_F), 12.0f, Vec3{0.0f, 0.0f, -1.0f},
	          "the near root 8 is below dist_bounds.x = 9; the far root 12 is the first hit in the bounds");
	check_miss(R2, bounded(ray, 8.5f, 11.0f),
	           "both roots, 8 and 12, are outside dist_bounds [8.5, 11] (handout §2.3)");
}

TEST_CASE("Sphere::hit: spheres behind the ray, and rays passing beside them, miss") {
	check_miss(R2, Ray(Vec3{0.0f, 0.0f, 10.0f}, Vec3{0.0f, 0.0f, 1.0f}), "both roots (-8 and -12) are negative");
	check_miss(R2, Ray(Vec3{2.5f, 0.0f, 10.0f}, DOWN), "the ray passes 2.5 from the centre of a sphere of radius 2");
	check_miss(R2, Ray(Vec3{0.0f, 2.02f, 10.0f}, 7.0f * DOWN), "the ray passes 2.02 from the centre (|dir| = 7)");
}

TEST_CASE("Sphere::hit: dist_bounds are inclusive at both ends, for both roots") {
	// Roots exactly 8 and 12 (every formula computes them without rounding here).
	Ray ray(Vec3{0.0f, 0.0f, 10.0f}, DOWN);
	const float e = 1e-6f;
	const Vec3 front{0.0f, 0.0f, 1.0f}, back{0.0f, 0.0f, -1.0f};
	check_hit(R2, bounded(ray, 8.0f, 8.0f), 8.0f, front, "dist_bounds = [8, 8]; the bounds are inclusive");
	check_hit(R2, bounded(ray, 8.0f * (1 - e), INF_F), 8.0f, front, "the near root 8 is just above dist_bounds.x");
	check_hit(R2, bounded(ray, 0.0f, 8.0f * (1 + e)), 8.0f, front, "the near root 8 is just below dist_bounds.y");
	check_hit(R2, bounded(ray, 8.0f * (1 + e), INF_F), 12.0f, back, "the near root 8 is just below dist_bounds.x");
	check_miss(R2, bounded(ray, 0.0f, 8.0f * (1 - e)), "the near root 8 is just beyond dist_bounds.y (handout §2.3)");
	check_hit(R2, bounded(ray, 12.0f, 12.0f), 12.0f, back, "dist_bounds = [12, 12]; the bounds are inclusive");
	check_hit(R2, bounded(ray, 9.0f, 12.0f * (1 + e)), 12.0f, back, "the far root 12 is just below dist_bounds.y");
	check_miss(R2, bounded(ray, 9.0f, 12.0f * (1 - e)), "the far root 12 is just beyond dist_bounds.y (handout §2.3)");
	check_miss(R2, bounded(ray, 12.0f * (1 + e), INF_F), "both roots are below dist_bounds.x (handout §2.3)");
}

TEST_CASE("Sphere::hit: tangent and nearly tangent rays give no NaN") {
	// Lines at distance r (1 +- 2^-k) from the centre: hit or miss may go either way within rounding,
	// but a hit must be a proper one (the oracle's tolerance grows like sqrt(eps) at tangency).
	RNG rng(99);
	for (int k = 8; k <= 30; k++) {
		for (float sign : {-1.0f, 0.0f, 1.0f}) {
			for (float scale : {1.0f, 0.01f, 50.0f}) {
				float r = 0.5f + 4.0f * rng.unit();
				float l = r * (1.0f + sign * std::ldexp(1.0f, -k));
				// The line x = l, y = 0, travelling along -z (rotated for variety), from z = 3r.
				float angle = 2.0f * PI_F * rng.unit();
				Vec3 side{std::cos(angle), std::sin(angle), 0.0f};
				Ray ray(l * side + Vec3{0.0f, 0.0f, 3.0f * r}, scale * DOWN);
				Sphere sphere{r};
				Trace got = sphere.hit(ray);
				std::string problem = hit_problem(expect_hit(sphere, ray), got, ray, "handout §2.2");
				INFO(describe(sphere, ray) << " (a ray at distance " << l << " from the centre): " << problem
				     << ". Clamp nothing: a negative discriminant is a miss, zero is a (tangent) hit (handout §2.3)");
				CHECK(problem.empty());
				if (!problem.empty()) return;
			}
		}
	}
}

TEST_CASE("Sphere::hit: small and distant spheres are hit accurately (numerically stable quadratic)") {
	// A sphere of radius r seen from distance D, rays aimed within 0.9 r of the centre: all must hit,
	// with relative t error < 1e-5. The stable form of handout §2.2 has errors of a few eps
	// (< 1e-6; its bound by shape_oracle.cpp's reasoning is ~3 K eps = 6e-6); b^2 - ac cancels
	// catastrophically when r / D is small: at r / D = 1e-4 two thirds of these rays miss and t is
	// off by up to 5e-4 (measured).
	struct Config {
		float r, D;
	};
	RNG rng(2718);
	for (Config c : {Config{1.0f, 1e4f}, Config{1e-3f, 1e3f}, Config{1e-2f, 1e2f}, Config{1e4f, 2e4f}}) {
		size_t misses = 0, inaccurate = 0, setup_errors = 0;
		double worst = 0.0;
		std::string example;
		Sphere sphere{c.r};
		for (int i = 0; i < 10000; i++) {
			Vec3 from = c.D * glm::normalize(Vec3{rng.unit() - 0.5f, rng.unit() - 0.5f, rng.unit() - 0.5f});
			// A target in the disc of radius 0.9 r through the centre, perpendicular to the view.
			Vec3 a = glm::normalize(glm::cross(from, Vec3{0.3f, 1.0f, 0.1f})), b = glm::normalize(glm::cross(from, a));
			float rho = 0.9f * c.r * std::sqrt(rng.unit()), phi = 2.0f * PI_F * rng.unit();
			Vec3 target = rho * std::cos(phi) * a + rho * std::sin(phi) * b;
			Ray ray(from, (target - from) * (0.5f + rng.unit()));
			double t0 = 0.0, t1 = 0.0;
			if (!sphere_roots(sphere, ray, t0, t1)) {
				setup_errors++; // cannot happen: every ray aims inside the sphere
				continue;
			}
			Trace got = sphere.hit(ray);
			if (!got.hit) {
				if (misses++ == 0) example = show(ray);
				continue;
			}
			double error = std::abs(got.distance - t0) / t0;
			worst = std::max(worst, error);
			if (!(error < 1e-5) && inaccurate++ == 0) example = show(ray);
		}
		INFO("radius " << c.r << " seen from distance " << c.D << ": " << misses << " of 10000 rays aimed inside the "
		     "sphere missed it, " << inaccurate << " hits had a relative error of t above 1e-5 (worst " << worst
		     << "). Use the numerically stable discriminant and roots of handout §2.2. First bad ray: " << example);
		CHECK(misses == 0);
		CHECK(inaccurate == 0);
		CHECK(setup_errors == 0);
	}
}

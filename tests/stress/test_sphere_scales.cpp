// Stress (handout §2.2): spheres tiny or huge relative to their distance are hit, accurately, and
// tangent rays give no NaN.
//
// With r / D = radius / distance small, b^2 and ac agree in their leading digits and the textbook
// discriminant b^2 - ac cancels catastrophically in float: it misses 31-45 % of true hits once
// r / D <= 1e-4 (testing-anchors §3). The stable form a (r - l)(r + l) does not.
#include "rng.h"
#include "stress_show.h"
#include "shapes.h"
#include "stress_count.h"
#include "stress_meshes.h"

#include "lab_catch2.h"

#include <cmath>

namespace {

using LVec3 = glm::tvec3<long double>;

// The near root of |o + t d| = r in long double with the stable form (no tolerance needed:
// 64-bit mantissas leave ~1e-8 relative error even at r / D = 1e-6).
long double near_root(const Ray& ray, float radius) {
	LVec3 o(ray.point), d(ray.dir);
	long double a = glm::dot(d, d), b = glm::dot(o, d);
	LVec3 closest = o - (b / a) * d;
	long double l = std::sqrt(glm::dot(closest, closest)), r = radius;
	long double disc = a * (r - l) * (r + l);
	return (-b - std::sqrt(disc)) / a;
}

// A ray from distance D = radius / ratio, in a random direction, aimed at a point of the sphere's
// disc (as seen from the origin) at most 0.9 of the disc's radius from its centre: a sure hit.
Ray aimed_ray(RNG& rng, float radius, float ratio, float aim) {
	Vec3 w = random_unit(rng);
	Vec3 side = glm::normalize(glm::cross(w, random_unit(rng)));
	Vec3 origin = (radius / ratio) * w;
	Vec3 target = aim * radius * side; // in the plane through the centre perpendicular to w
	return Ray(origin, glm::normalize(target - origin));
}

const float RADII[] = {1e-4f, 1.0f, 1e4f};
const float RATIOS[] = {1e-1f, 1e-2f, 1e-3f, 1e-4f, 1e-5f, 1e-6f};

} // namespace

TEST_CASE("Stress: tiny and huge spheres (radius / distance 1e-1 ... 1e-6) are hit, with relative distance error < 1e-5",
          "[stress][task2]") {
	RNG rng(77);
	Stress_Count misses, inaccurate;
	for (float radius : RADII) {
		for (float ratio : RATIOS) {
			Sphere sphere{radius};
			for (int i = 0; i < 2000; i++) {
				Ray ray = aimed_ray(rng, radius, ratio, 0.9f * rng.unit());
				Trace got = sphere.hit(ray);
				auto describe = [&] {
					return "radius " + std::to_string(radius) + ", " + stress::show(ray) + ", t = " +
					       std::to_string(got.distance);
				};
				misses.add(!got.hit, describe);
				if (!got.hit) continue;
				long double t = near_root(ray, radius);
				inaccurate.add(!(std::abs(got.distance - t) < 1e-5L * t), describe);
			}
		}
	}
	INFO("Sphere::hit: " << misses.report("sure hits were missed") << ".\n"
	     << "b^2 - ac cancels when the sphere is small or far; use b^2 - ac = a (r - l)(r + l) with l the distance of "
	        "the centre from the ray (handout §2.2).");
	CHECK(misses.failures == 0);
	INFO("Sphere::hit: " << inaccurate.report("hits were more than 1e-5 (relative) from the true distance") << ".\n"
	     << "Compute the near root as q / a or c / q with q = -(b + sign(b) sqrt(disc)) (handout §2.2).");
	CHECK(inaccurate.failures == 0);
	std::printf("stress count: sphere misses %zu of %zu, inaccurate %zu\n", misses.failures, misses.inputs,
	            inaccurate.failures);
}

TEST_CASE("Stress: tangent and nearly tangent rays at every scale give no NaN", "[stress][task2]") {
	RNG rng(78);
	Stress_Count nans;
	for (float radius : RADII) {
		for (float ratio : RATIOS) {
			Sphere sphere{radius};
			for (int i = 0; i < 1000; i++) {
				// Aimed at the silhouette, +- a few ulps.
				float aim = std::nextafter(1.0f, 0.0f) + float(int(rng.integer(5)) - 2) * 0x1p-24f;
				Ray ray = aimed_ray(rng, radius, ratio, aim);
				Trace got = sphere.hit(ray);
				bool bad = got.hit && !(std::isfinite(got.distance) && is_finite(got.position) && is_finite(got.normal) &&
				                        std::abs(glm::length(got.normal) - 1.0f) < 1e-3f);
				nans.add(bad, [&] { return "radius " + std::to_string(radius) + ", " + stress::show(ray); });
			}
		}
	}
	INFO("Sphere::hit: " << nans.report("tangent rays returned a hit with a NaN or infinite distance, position or "
	                                    "normal")
	                     << ". Reject a negative or NaN discriminant before its square root (handout §2.2).");
	CHECK(nans.failures == 0);
	std::printf("stress count: tangent-ray NaN %zu of %zu\n", nans.failures, nans.inputs);
}

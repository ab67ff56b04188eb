#include "bench_rays.h"

#include <random>

std::vector<Ray> primary_rays(const Camera& camera, int width, int height) {
	std::vector<Ray> rays;
	rays.reserve(size_t(width) * height);
	for (int y = 0; y < height; y++)
		for (int x = 0; x < width; x++) rays.push_back(camera.generate_ray(Vec2{(x + 0.5f) / width, (y + 0.5f) / height}));
	return rays;
}

Ray_Sets make_ray_sets(const Bench_Geometry& geometry, std::vector<Ray> primary, const std::vector<float>& primary_hits,
                       size_t secondary_count) {
	Ray_Sets sets;
	std::vector<Vec3> surface_points;
	for (size_t i = 0; i < primary.size(); i++)
		if (primary_hits[i] < INF_F) surface_points.push_back(primary[i].at(primary_hits[i]));
	sets.primary = std::move(primary);
	if (surface_points.empty()) return sets;

	// Offsets that keep a ray from re-hitting the surface it leaves, relative to the scene's size.
	const float extent = glm::length(geometry.bounds.max - geometry.bounds.min);
	const float epsilon = 1e-5f * extent;
	std::mt19937 rng(1);
	std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
	std::uniform_int_distribution<size_t> pick(0, surface_points.size() - 1);
	for (size_t i = 0; i < secondary_count; i++) {
		Vec3 from = surface_points[pick(rng)];
		// Uniform direction on the sphere: z = 1 - 2 u1, phi = 2 pi u2.
		float z = 1.0f - 2.0f * uniform(rng), phi = 2.0f * PI_F * uniform(rng);
		float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
		sets.incoherent.push_back(Ray(from, Vec3{r * std::cos(phi), r * std::sin(phi), z}, Vec2{epsilon, INF_F}));

		Vec3 to = geometry.bounds.min + Vec3{uniform(rng), uniform(rng), uniform(rng)} * (geometry.bounds.max - geometry.bounds.min);
		Vec3 dir = to - from;
		float length = glm::length(dir);
		if (!(length > 2.0f * epsilon)) continue;
		// t in [epsilon, length - epsilon] along the unit direction: the segment between the points.
		sets.occlusion.push_back(Ray(from, dir / length, Vec2{epsilon, length - epsilon}));
	}
	return sets;
}

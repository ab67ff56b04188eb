#pragma once
// Area lights: the emissive shapes of a scene, in world space, for light sampling (task 6).
//
// Each emissive object is one light. A direction towards light i is drawn by choosing a point
// uniformly by area on it; its solid-angle density is the area density converted by
// dist^2 / |cos theta_light|, summed over every point of the light along the direction (a sphere
// is crossed twice), because any of them could have been the sampled point.
#include "instance.h"
#include "material.h"

#include <vector>

struct Light_Triangle {
	Vec3 p0, p1, p2;
};

struct Area_Light {
	std::vector<Light_Triangle> triangles; // a mesh light, or
	std::vector<float> cdf;                // running sum of triangle areas
	Vec3 center{0.0f};                     // a sphere light (when triangles is empty)
	float radius = 0.0f;
	float area = 0.0f;
};

class Area_Lights {
public:
	// Collects the emissive objects. Spheres must be uniformly scaled (Input_Error otherwise).
	void build(const std::vector<Instance>& objects, const std::vector<Material>& materials);

	size_t count() const {
		return lights.size();
	}
	// A unit direction from `from` towards a uniformly chosen point of light i.
	Vec3 sample(size_t i, RNG& rng, Vec3 from) const;
	// The solid-angle density of sample(i, ., from) producing `dir` (unit).
	float pdf(size_t i, Vec3 from, Vec3 dir) const;

private:
	std::vector<Area_Light> lights;
};

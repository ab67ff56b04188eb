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
	Vec3 normal; // unit, cross(p1 - p0, p2 - p0) normalized: its front side
};

struct Area_Light {
	std::vector<Light_Triangle> triangles; // a mesh light, or
	std::vector<float> cdf;                // running sum of triangle areas
	Vec3 center{0.0f};                     // a sphere light (when triangles is empty)
	float radius = 0.0f;
	bool inside_out = false;               // a sphere turned inside out (emits towards its centre)
	float area = 0.0f;
	uint32_t material = 0;                 // its emission is this material's
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

	// For next-event estimation (Pathtracer::sample_light) and the choice of a light by power
	// (framework/scene/light_distribution.h): a point chosen as sample() chooses it, with the unit
	// normal of the side it emits from; the solid-angle density, seen from `from`, of choosing that
	// point, dist^2 / (|cos theta_light| area); the light an object is (-1: none); a light's area
	// and material.
	struct Point {
		Vec3 position, normal;
	};
	Point sample_point(size_t i, RNG& rng) const;
	float point_pdf(size_t i, Vec3 from, Vec3 point, Vec3 normal) const;
	int light_of(uint32_t object) const;
	float area(size_t i) const {
		return lights[i].area;
	}
	uint32_t material(size_t i) const {
		return lights[i].material;
	}
	// Light i's shape, for the light tree's bounds (framework/scene/light_bounds.h).
	const Area_Light& light(size_t i) const {
		return lights[i];
	}

private:
	std::vector<Area_Light> lights;
	std::vector<int> light_of_object; // by object index (Instance::index)
};

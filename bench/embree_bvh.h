#pragma once
// Embree 3 on the benchmark's triangles, for comparison (compiled only when Embree is found).
// The device builds with one thread (threads=1), like our build; tracing may use many threads.
#include "tri_mesh.h"

#include <cstddef>
#include <vector>

class Embree_BVH {
public:
	// Builds the scene with RTC_BUILD_QUALITY_HIGH.
	explicit Embree_BVH(const std::vector<Triangle>& triangles);
	~Embree_BVH();
	Embree_BVH(const Embree_BVH&) = delete;
	Embree_BVH& operator=(const Embree_BVH&) = delete;

	// rtcIntersect1: the closest hit distance, INF_F for a miss.
	float closest_hit(const Ray& ray) const;
	// rtcIntersect1, then the record BVH::hit returns (Triangle::hit's): the hit point and the vertex
	// normals interpolated at Embree's (u, v), normalized. `triangles` as given to the constructor.
	Trace hit(const Ray& ray, const std::vector<Triangle>& triangles) const;
	// rtcOccluded1: whether anything is hit with t in ray.dist_bounds.
	bool occluded(const Ray& ray) const;

	double build_seconds = 0.0; // rtcCommitScene, CPU time
	size_t bytes = 0;           // device memory in use after the build (vertex and index buffers included)

private:
	void* device_ = nullptr; // RTCDevice and RTCScene, kept opaque so this header needs no Embree
	void* scene_ = nullptr;
};

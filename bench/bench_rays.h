#pragma once
// The three ray sets of the benchmark, generated once and traced by every method.
//   primary:    one ray per pixel of the camera's film (coherent: neighbours take similar paths);
//   incoherent: from the surface points the primary rays hit, in directions uniform on the sphere
//               (closest hit; like diffuse bounces, neighbouring rays share nothing);
//   occlusion:  from the same surface points towards uniform random points in the scene's box,
//               ending just before them (shadow rays: any hit will do).
#include "bench_geometry.h"

#include <vector>

struct Ray_Sets {
	std::vector<Ray> primary, incoherent, occlusion;
};

// `primary_hits` gives the hit distance of every primary ray (INF_F for a miss).
std::vector<Ray> primary_rays(const Camera& camera, int width, int height);
Ray_Sets make_ray_sets(const Bench_Geometry& geometry, std::vector<Ray> primary, const std::vector<float>& primary_hits,
                       size_t secondary_count);

#pragma once
// Properties of a built BVH<Triangle>: its SAH cost, its memory, and the work a ray does in it.
#include "tri_mesh.h"

#include <vector>

// SAH cost with C_trav = C_isect = 1: sum over interior nodes of S_n / S_root, plus sum over leaves
// of S_n / S_root * N_n (the expected number of node and triangle tests of a random line through the
// root's box).
double sah_cost(const BVH<Triangle>& bvh);

// Bytes held by the BVH: its nodes and triangles (the accelerator's own: Accelerator::bytes).
size_t bvh_bytes(const BVH<Triangle>& bvh);

struct Visit_Counts {
	double nodes = 0;     // per ray: nodes whose box overlaps the ray's segment up to its closest hit
	double triangles = 0; // per ray: triangles in the leaves among them
};
// Averaged over `rays`, with `hits[i]` the closest hit distance of rays[i] (INF_F for a miss). This
// is what an ideal front-to-back traversal visits (framework/core/bvh_visits.h).
Visit_Counts visit_counts(const BVH<Triangle>& bvh, const std::vector<Ray>& rays, const std::vector<float>& hits);

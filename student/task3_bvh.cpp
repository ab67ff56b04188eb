// Task 3: bounding volume hierarchy. Handout: handouts/task3_bvh.md
#include "bvh.h"
#include "instance.h"
#include "tri_mesh.h"

namespace {
// Your helper functions go here. The anonymous namespace keeps them private to this file: two task
// files that each define a helper of the same name (say `lerp`) would otherwise not link together.
} // namespace

bool BBox::hit(const Ray& ray, Vec2& times) const {
	// TODO (Task 3, handout §3.1): ray-box slab test.
	// - For each axis, the ray is between the two planes for t in [(min - o) / d, (max - o) / d]
	//   (swap the ends when d < 0). Intersect these three intervals with `times`: the largest
	//   entry and the smallest exit.
	// - If t_enter <= t_exit, store [t_enter, t_exit] in `times` and return true.
	// - Careful: boxes can be flat (min == max on an axis: use <=, not <), rays can start inside
	//   the box, and for d = 0 with the origin on a plane, 0 * inf = NaN must not cause a miss.
	(void)ray, (void)times;
	return false;
}

template<typename Primitive> void BVH<Primitive>::build(std::vector<Primitive>&& prims, size_t max_leaf_size) {
	// TODO (Task 3, handout §3.2): build a BVH with the surface area heuristic (SAH).
	// A node with at most max_leaf_size primitives is a leaf (l == r). Otherwise, for each of the
	// three axes, bin the primitives by centroid into 16 buckets, evaluate the SAH cost
	// S_A N_A + S_B N_B of every split between buckets, split at the cheapest one
	// (std::partition keeps each node's primitives contiguous), and continue with both halves.
	// If all centroids coincide, nothing can split them: make a leaf.
	//
	// This starter version puts every primitive into one leaf, so hit() below tests them all:
	// correct, but slow for large meshes.
	(void)max_leaf_size;
	nodes.clear();
	primitives = std::move(prims);
	BBox box;
	for (const Primitive& p : primitives) box.enclose(p.bbox());
	root_idx = new_node(box, 0, primitives.size(), 0, 0);
}

template<typename Primitive> Trace BVH<Primitive>::hit(const Ray& ray) const {
	// TODO (Task 3, handout §3.3): traverse the tree. Skip nodes whose box the ray misses, visit
	// the nearer child first, and skip the farther one when its box starts beyond the closest hit
	// found so far (shrink a copy of the ray's dist_bounds.y to that hit). An explicit stack of
	// (node, entry t) is faster than recursion.
	//
	// This starter version tests every primitive, each against the ray shortened to the closest
	// hit so far (a primitive farther away is then a miss, found sooner); on a tie the first wins.
	Ray closest_ray = ray;
	Trace closest;
	for (const Primitive& prim : primitives) {
		Trace hit = prim.hit(closest_ray);
		if (hit.hit && (!closest.hit || hit.distance < closest.distance)) {
			closest = hit;
			closest_ray.dist_bounds.y = hit.distance;
		}
	}
	return closest;
}

// The framework builds BVHs of triangles (inside meshes) and of scene objects.
template class BVH<Triangle>;
template class BVH<Instance>;

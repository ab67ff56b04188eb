#pragma once
// How the framework queries a finished BVH (Tri_Mesh::hit, Scene::hit): the closest hit, and
// whether anything is hit (an occlusion query). A program links one of two implementations, chosen
// with its tasks (cmake/lab.cmake, lab_link_tasks):
// - where tasks 2 and 3 are both the reference, the fast one (shipped compiled): it folds the
//   finished tree into wide nodes (a mesh's the way of least SAH cost) and packs a mesh's
//   triangles, tests them with the widest vectors the CPU has, finds the closest (triangle, t, u,
//   v; of several at one t the first in bvh.primitives), and makes that triangle's record as
//   Triangle::hit makes it, bit for bit;
// - otherwise the plain one (framework/accel/plain_accelerator.cpp): BVH::hit, so that a student's
//   BBox::hit, BVH::hit and Triangle::hit are what runs, end to end.
// Either way, hit() returns the record Primitive::hit makes, as BVH::hit does.
#include "bvh.h"

#include <memory>

struct Wide_BVH; // the fast implementation's data

template<typename Primitive> class Accelerator {
public:
	Accelerator() = default; // queries then go to BVH::hit
	// Prepares the queries of `bvh`, whose build() has returned. Rebuilding the tree needs a new one.
	explicit Accelerator(const BVH<Primitive>& bvh);

	// The closest hit with t in ray.dist_bounds. `bvh`: the tree this was made from.
	Trace hit(const BVH<Primitive>& bvh, const Ray& ray) const;
	// Whether anything is hit with t in ray.dist_bounds; it may stop at the first hit found.
	bool occluded(const BVH<Primitive>& bvh, const Ray& ray) const;

	// Bytes of the accelerator's own data: its memory use.
	size_t bytes() const;

private:
	std::shared_ptr<const Wide_BVH> wide; // the fast implementation's; null in the plain one
};

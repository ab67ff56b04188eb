#pragma once
#include "bbox.h"
#include "trace.h"

#include <cstdint>
#include <vector>

// Bounding volume hierarchy over primitives that have `BBox bbox() const` and
// `Trace hit(const Ray&) const` (Triangle and Instance in this lab).
//
// Layout: all nodes live in `nodes`; node `root_idx` is the root. A node covers
// primitives[start, start + size). An interior node has two children nodes[l] and nodes[r]; a
// leaf has l == r (by convention both equal to its own index).
template<typename Primitive> class BVH {
public:
	struct Node {
		BBox bbox;
		size_t start = 0, size = 0, l = 0, r = 0;

		bool is_leaf() const {
			return l == r;
		}
	};

	BVH() = default;
	BVH(std::vector<Primitive>&& primitives, size_t max_leaf_size = 1) {
		build(std::move(primitives), max_leaf_size);
	}

	// Task 3 (student/task3_bvh.cpp): build a binned-SAH tree over `primitives` (reordering them),
	// with at most max_leaf_size primitives per leaf unless they cannot be split.
	void build(std::vector<Primitive>&& primitives, size_t max_leaf_size = 1);

	// Task 3: the closest hit with t in ray.dist_bounds, visiting children front to back.
	Trace hit(const Ray& ray) const;

	// Not part of task 3: whether anything is hit with t in ray.dist_bounds, stopping at the first
	// hit found (an any-hit query, as for shadow rays; bench/bvh_bench). The reference defines it.
	bool occluded(const Ray& ray) const;

	BBox bbox() const {
		return nodes.empty() ? BBox{} : nodes[root_idx].bbox;
	}

	// Appends a node and returns its index.
	size_t new_node(BBox bbox = {}, size_t start = 0, size_t size = 0, size_t l = 0, size_t r = 0) {
		nodes.push_back(Node{bbox, start, size, l, r});
		return nodes.size() - 1;
	}

	std::vector<Primitive> primitives;
	std::vector<Node> nodes;
	size_t root_idx = 0;

	// Traversal data: NOT part of Task 3 (your build() may leave flat_pairs empty; your hit() need
	// not use it). The reference build() fills it from `nodes`, and its hit() traverses it
	// instead: the same tree, laid out for speed (bench/README.md).
	struct Flat_Node { // 32 bytes
		Vec3 min;
		uint32_t first; // interior: its children are flat_pairs[first]; leaf: its first primitive
		Vec3 max;
		uint32_t count; // leaf: number of primitives (>= 1); 0: interior node
	};
	struct alignas(64) Flat_Pair { // two siblings, in one 64-byte cache line
		Flat_Node child[2];
	};
	std::vector<Flat_Pair> flat_pairs; // flat_pairs[0].child[0] is the root; empty without primitives
};

#pragma once
#include "bbox.h"
#include "trace.h"

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
};

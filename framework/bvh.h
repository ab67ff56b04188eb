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

	// Traversal data: NOT part of Task 3 (your build() may leave wide_nodes empty; your hit() need
	// not use it). The reference build() fills it from `nodes`, and its hit() traverses it instead:
	// the same tree with two of every three levels folded in, so that a node has up to eight
	// children whose boxes two 4-wide slab tests handle (bench/README.md).
	struct alignas(64) Wide_Node { // 288 bytes, padded to 320: five cache lines
		static constexpr int WIDTH = 8; // children per node
		// The children's boxes, one array per bound and axis, so that one 4-wide instruction
		// handles the same bound of four children. An unused slot holds an empty box.
		float min_x[WIDTH], min_y[WIDTH], min_z[WIDTH], max_x[WIDTH], max_y[WIDTH], max_z[WIDTH];
		uint32_t first[WIDTH]; // interior child: its index in wide_nodes; leaf: its first primitive,
		                       // or in BVH<Triangle> its first triangle pack
		uint32_t count[WIDTH]; // leaf: its number of primitives (>= 1); interior child or unused: 0
		                       // (an unused slot has first = ~0u and an empty box)
		uint32_t start[WIDTH]; // leaf: its first primitive (as Node::start); otherwise 0. In the last
		                       // line, read only by closest-hit queries, to fetch a leaf's triangles.
	};
	std::vector<Wide_Node> wide_nodes; // wide_nodes[0] is the root; empty without primitives

	// BVH<Triangle> only: each leaf's triangles in packs of four, vertex v0 and edges e1 = v1 - v0,
	// e2 = v2 - v0 one array per coordinate, so that one Möller–Trumbore test handles four. A
	// leaf's packs are consecutive; lanes past its last triangle are unused (index ~0u).
	struct alignas(32) Triangle_Pack { // 160 bytes, against 4 x 72 for the Triangles themselves
		float v0[3][4], e1[3][4], e2[3][4];
		uint32_t index[4]; // the triangle in `primitives`
	};
	std::vector<Triangle_Pack> triangle_packs;
};

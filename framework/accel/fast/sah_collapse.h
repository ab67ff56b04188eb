#pragma once
// Which nodes of a binary BVH<Triangle> become the children of each wide node: the choice of least
// SAH cost, by dynamic programming over the binary tree (Ylitie, Karras and Laine 2017, "Efficient
// incoherent ray traversal on GPUs through compressed wide BVHs", §3). A wide node takes up to
// Wide_Node::WIDTH children, each a wide node or a leaf; a leaf may be a whole small subtree (its
// triangles are consecutive in BVH::primitives), tested pack by pack.
#include "bvh.h"
#include "tri_mesh.h"
#include "wide_bvh.h"

#include <cstddef>
#include <cstdint>
#include <vector>

struct Wide_Child {
	size_t binary; // the binary node it is made of
	bool leaf;     // its subtree's triangles, in packs; otherwise a wide node made from `binary`
};

class Sah_Collapse {
public:
	// The SAH's costs: a ray's expected work is the sum, over the boxes it may enter, of each box's
	// surface area times the work of entering it: a node's test for a wide node, a pack's test per
	// pack for a leaf. A node's test counts as four packs' (measured: bench/README.md, "Issue 37: the
	// wide tree of least SAH cost"): a leaf's packs are consecutive and fetched together, while each
	// level of nodes waits on its own fetch.
	static constexpr float NODE_COST = 4.0f, PACK_COST = 1.0f;
	// A leaf made of a subtree holds at most this many triangles (a leaf of the binary tree is kept
	// whatever its size).
	static constexpr size_t MAX_LEAF_TRIANGLES = 16;

	explicit Sah_Collapse(const BVH<Triangle>& bvh);

	// The children of the wide node made from interior binary node `binary` (a leaf root: itself).
	std::vector<Wide_Child> children(size_t binary) const;

	// The SAH cost of the wide tree from the root down, divided by the root's surface area: the
	// least that any choice of children reaches.
	float cost() const;

private:
	// Per binary node n, C(n, i): the least cost of n's subtree as at most i children of one wide
	// node (cost[i - 1]). One child: a leaf of its triangles or a wide node (its test, then its own
	// children); more: n's two binary children share them.
	struct Choice {
		float cost[Wide_Node::WIDTH];
		uint8_t left[Wide_Node::WIDTH]; // for i >= 2 children shared by n's two: how many go left
		bool leaf;                      // C(n, 1) is the leaf's
	};
	static float share(const Choice& l, const Choice& r, int count, uint8_t& left);
	void append_children(size_t binary, int count, std::vector<Wide_Child>& out) const;

	const BVH<Triangle>& bvh;
	std::vector<Choice> choices;
};

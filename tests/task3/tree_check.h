#pragma once
// What the task-3 grader measures on a built tree (the student's, returned by the subject as a
// protocol::Tree, or the reference's, built here in the judge): whether it keeps the layout
// contract of bvh.h, its SAH cost, and how many primitives an ideal traversal of it tests. None of
// this builds or traverses a tree for a closest hit: the expected hits come from the reference.
#include "protocol.h"

#include <string>
#include <vector>

namespace task3 {

// The reference's tree (BVH::build of the reference, in the judge), in the form the subject returns.
template<typename Primitive> protocol::Tree tree_of(const BVH<Primitive>& bvh) {
	protocol::Tree tree;
	for (const auto& n : bvh.nodes) tree.nodes.push_back({n.bbox, n.start, n.size, n.l, n.r});
	tree.root_idx = bvh.root_idx;
	return tree;
}

// The first violation of the BVH layout contract (bvh.h, handout §3.2) in a tree over primitives
// whose boxes are `boxes` (in the tree's order), or "" if none: the root covers every primitive,
// each interior node's children split its range into two non-empty parts, nothing is shared or
// cyclic, every node box is the union of its primitives' boxes, and a leaf holds at most
// max_leaf_size primitives unless all their centroids coincide.
std::string structure_problem(const protocol::Tree& tree, const std::vector<BBox>& boxes, size_t max_leaf_size);

// SAH cost of a (valid) tree relative to its root box, C_trav = C_isect = 1:
//   sum over interior nodes of S(node) / S(root) + sum over leaves of N(leaf) S(leaf) / S(root),
// with boxes recomputed tightly from `boxes`, so that the cost measures how the tree groups them.
double sah_cost(const protocol::Tree& tree, const std::vector<BBox>& boxes);

// The primitives an ideal front-to-back traversal of a (valid) tree tests for `ray` whose closest
// hit is at `closest` (INF_F for a miss): those of the leaves whose boxes the segment
// [dist_bounds.x, closest] overlaps (the reference BBox::hit decides overlap).
size_t ideal_tests(const protocol::Tree& tree, const Ray& ray, float closest);

} // namespace task3

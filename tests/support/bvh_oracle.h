#pragma once
// An independent BVH for the task 3 grader: a small binned-SAH builder, the SAH cost of a tree,
// an ideal front-to-back traversal, and a check of the structure of a student's BVH<Primitive>.
// Nothing here calls BBox::hit or BVH::build/hit, so it grades them without trusting them.
#include "bvh.h"
#include "trace.h"

#include <functional>
#include <string>
#include <vector>

namespace oracle {

// A tree over primitives 0..n-1. A node covers order[begin, end); a leaf has no children (-1).
struct Node {
	BBox box;
	size_t begin = 0, end = 0;
	long left = -1, right = -1;

	bool is_leaf() const {
		return left < 0;
	}
};

struct Tree {
	std::vector<Node> nodes; // nodes[0] is the root (absent for zero primitives)
	std::vector<size_t> order; // primitive indices in the order the leaves cover them
};

// Binned SAH with `buckets` buckets per axis over the centroids of `boxes`, C_trav = C_isect = 1.
// A node becomes a leaf when it holds at most max_leaf_size primitives or all its centroids
// coincide; otherwise it is split at the cheapest bucket boundary.
Tree build_binned_sah(const std::vector<BBox>& boxes, size_t max_leaf_size, int buckets = 16);

// SAH cost of a tree relative to its root box (C_trav = C_isect = 1):
//   sum over interior nodes of S(node) / S(root) + sum over leaves of N(leaf) S(leaf) / S(root).
// Boxes are recomputed tightly from `boxes`, so the cost measures how the tree groups primitives.
double sah_cost(const Tree& tree, const std::vector<BBox>& boxes);

// Slab test written independently of the student's BBox::hit: [t0, t1] narrows to the overlap.
bool slab(const BBox& box, const Ray& ray, float& t0, float& t1);

// Ideal front-to-back closest-hit traversal: nearer child first, a node skipped when its entry t
// lies beyond the closest hit so far. hit_primitive(i, ray) intersects primitive i.
Trace traverse(const Tree& tree, const Ray& ray, const std::function<Trace(size_t, const Ray&)>& hit_primitive);

// The same tree shape as a student's BVH (whose structure check_structure has accepted); its
// primitive i is bvh.primitives[i].
template<typename Primitive> Tree tree_of(const BVH<Primitive>& bvh) {
	Tree tree;
	for (size_t i = 0; i < bvh.primitives.size(); i++) tree.order.push_back(i);
	if (bvh.nodes.empty()) return tree;
	std::vector<std::pair<size_t, size_t>> todo{{bvh.root_idx, 0}}; // (student node, our node)
	tree.nodes.emplace_back();
	while (!todo.empty()) {
		auto [from, to] = todo.back();
		todo.pop_back();
		const auto& n = bvh.nodes[from];
		tree.nodes[to].box = n.bbox;
		tree.nodes[to].begin = n.start;
		tree.nodes[to].end = n.start + n.size;
		if (n.is_leaf()) continue;
		for (size_t child : {n.l, n.r}) {
			tree.nodes.emplace_back();
			(child == n.l ? tree.nodes[to].left : tree.nodes[to].right) = long(tree.nodes.size() - 1);
			todo.push_back({child, tree.nodes.size() - 1});
		}
	}
	return tree;
}

// The first violation of the BVH layout contract (bvh.h, handout §3.2) in a built tree, or "" if
// none: the root covers every primitive, each interior node's children split its range into two
// non-empty parts, nothing is shared or cyclic, every node box is the union of its primitives'
// boxes, and a leaf holds at most max_leaf_size primitives unless all their centroids coincide.
template<typename Primitive> std::string check_structure(const BVH<Primitive>& bvh, size_t max_leaf_size) {
	size_t n = bvh.primitives.size();
	if (bvh.nodes.empty()) return n == 0 ? "" : "there are primitives but no nodes";
	if (bvh.root_idx >= bvh.nodes.size()) return "root_idx is not the index of a node";
	const auto& root = bvh.nodes[bvh.root_idx];
	if (root.start != 0 || root.size != n) return "the root must cover primitives[0, primitives.size())";

	std::vector<bool> seen(bvh.nodes.size(), false);
	std::vector<size_t> todo{bvh.root_idx};
	while (!todo.empty()) {
		size_t idx = todo.back();
		todo.pop_back();
		if (seen[idx]) return "node " + std::to_string(idx) + " is reachable twice (the tree has a cycle or shared node)";
		seen[idx] = true;
		const auto& node = bvh.nodes[idx];
		std::string where = "node " + std::to_string(idx) + " (start " + std::to_string(node.start) + ", size " +
		                    std::to_string(node.size) + "): ";

		BBox box;
		for (size_t i = node.start; i < node.start + node.size; i++) box.enclose(bvh.primitives[i].bbox());
		if (node.size > 0 && !(box.min == node.bbox.min && box.max == node.bbox.max))
			return where + "its bbox is not the union of its primitives' boxes (too loose or too small)";

		if (node.is_leaf()) {
			if (node.size > max_leaf_size) {
				Vec3 c = bvh.primitives[node.start].bbox().center();
				for (size_t i = node.start; i < node.start + node.size; i++)
					if (bvh.primitives[i].bbox().center() != c)
						return where + "a leaf with more than max_leaf_size = " + std::to_string(max_leaf_size) +
						       " primitives whose centroids do not all coincide; it should have been split";
			}
			continue;
		}
		if (node.l >= bvh.nodes.size() || node.r >= bvh.nodes.size()) return where + "a child index is not a node";
		const auto& a = bvh.nodes[node.l];
		const auto& b = bvh.nodes[node.r];
		if (a.size == 0 || b.size == 0) return where + "an interior node with an empty child";
		const auto& first = a.start <= b.start ? a : b;
		const auto& second = a.start <= b.start ? b : a;
		if (first.start != node.start || second.start != first.start + first.size ||
		    first.size + second.size != node.size)
			return where + "its children's ranges do not split its own range [start, start + size) in two";
		todo.push_back(node.l);
		todo.push_back(node.r);
	}
	return "";
}

} // namespace oracle

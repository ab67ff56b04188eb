#include "tree_check.h"

#include <algorithm>

namespace task3 {

std::string structure_problem(const protocol::Tree& tree, const std::vector<BBox>& boxes, size_t max_leaf_size) {
	size_t n = boxes.size();
	if (tree.nodes.empty()) return n == 0 ? "" : "there are primitives but no nodes";
	if (tree.root_idx >= tree.nodes.size()) return "root_idx is not the index of a node";
	const auto& root = tree.nodes[tree.root_idx];
	if (root.start != 0 || root.size != n) return "the root must cover primitives[0, primitives.size())";

	std::vector<bool> seen(tree.nodes.size(), false);
	std::vector<uint64_t> todo{tree.root_idx};
	while (!todo.empty()) {
		uint64_t idx = todo.back();
		todo.pop_back();
		if (seen[idx]) return "node " + std::to_string(idx) + " is reachable twice (the tree has a cycle or shared node)";
		seen[idx] = true;
		const auto& node = tree.nodes[idx];
		std::string where = "node " + std::to_string(idx) + " (start " + std::to_string(node.start) + ", size " +
		                    std::to_string(node.size) + "): ";
		if (node.start > n || node.size > n - node.start) return where + "its range is not within the primitives";

		BBox box;
		for (uint64_t i = node.start; i < node.start + node.size; i++) box.enclose(boxes[i]);
		if (node.size > 0 && !(box.min == node.bbox.min && box.max == node.bbox.max))
			return where + "its bbox is not the union of its primitives' boxes (too loose or too small)";

		if (node.l == node.r) { // a leaf (bvh.h)
			if (node.size > max_leaf_size) {
				Vec3 c = boxes[node.start].center();
				for (uint64_t i = node.start; i < node.start + node.size; i++)
					if (boxes[i].center() != c)
						return where + "a leaf with more than max_leaf_size = " + std::to_string(max_leaf_size) +
						       " primitives whose centroids do not all coincide; it should have been split";
			}
			continue;
		}
		if (node.l >= tree.nodes.size() || node.r >= tree.nodes.size()) return where + "a child index is not a node";
		const auto& a = tree.nodes[node.l];
		const auto& b = tree.nodes[node.r];
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

double sah_cost(const protocol::Tree& tree, const std::vector<BBox>& boxes) {
	if (tree.nodes.empty()) return 0.0;
	double total = 0.0;
	std::vector<uint64_t> todo{tree.root_idx};
	while (!todo.empty()) {
		const auto& node = tree.nodes[todo.back()];
		todo.pop_back();
		BBox box;
		for (uint64_t i = node.start; i < node.start + node.size; i++) box.enclose(boxes[i]);
		bool leaf = node.l == node.r;
		total += double(box.surface_area()) * (leaf ? double(node.size) : 1.0);
		if (!leaf) todo.insert(todo.end(), {node.l, node.r});
	}
	BBox root;
	for (const BBox& b : boxes) root.enclose(b);
	return total / double(root.surface_area());
}

size_t ideal_tests(const protocol::Tree& tree, const Ray& ray, float closest) {
	if (tree.nodes.empty()) return 0;
	Ray segment = ray;
	segment.dist_bounds.y = std::min(ray.dist_bounds.y, closest);
	size_t tests = 0;
	std::vector<uint64_t> todo{tree.root_idx};
	while (!todo.empty()) {
		const auto& node = tree.nodes[todo.back()];
		todo.pop_back();
		Vec2 times = segment.dist_bounds;
		if (!node.bbox.hit(segment, times)) continue;
		if (node.l == node.r) {
			tests += node.size;
		} else {
			todo.insert(todo.end(), {node.l, node.r});
		}
	}
	return tests;
}

} // namespace task3

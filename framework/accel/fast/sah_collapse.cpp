#include "sah_collapse.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace {

constexpr int WIDTH = Wide_Node::WIDTH;

// A box's surface area for the costs, at most 1e25: the costs of a tree whose boxes span float's
// range (or hold a broken triangle's NaN) stay finite and comparable, summed over a million nodes.
float area_of(const BBox& box) {
	constexpr float LARGEST = 1e25f;
	float area = box.surface_area();
	return area <= LARGEST ? area : LARGEST; // (NaN fails the comparison)
}

} // namespace

// Ylitie et al.'s recurrence, with A(n) the area of n's box and P(n) its packs:
//   C(n, 1) = min(A(n) P(n) PACK_COST, A(n) NODE_COST + S(n, WIDTH))   (a leaf, or a wide node)
//   C(n, i) = min(C(n, 1), S(n, i))                                      (i >= 2)
//   S(n, i) = min over 0 < k < i of C(left, k) + C(right, i - k)        (n's children share i)
// computed children first. A leaf of the binary tree can only be a leaf: C(n, i) = its leaf's cost.
Sah_Collapse::Sah_Collapse(const BVH<Triangle>& bvh_) : bvh(bvh_), choices(bvh_.nodes.size()) {
	if (bvh.nodes.empty()) return;
	std::vector<size_t> order, todo{bvh.root_idx}; // parents before children
	while (!todo.empty()) {
		size_t n = todo.back();
		todo.pop_back();
		order.push_back(n);
		if (!bvh.nodes[n].is_leaf()) todo.push_back(bvh.nodes[n].l), todo.push_back(bvh.nodes[n].r);
	}
	for (auto n = order.rbegin(); n != order.rend(); ++n) {
		const auto& node = bvh.nodes[*n];
		Choice& c = choices[*n];
		float area = area_of(node.bbox);
		float leaf = area * float((node.size + 3) / 4) * PACK_COST;
		if (node.is_leaf()) {
			std::fill(std::begin(c.cost), std::end(c.cost), leaf);
			std::fill(std::begin(c.left), std::end(c.left), uint8_t(0));
			c.leaf = true;
			continue;
		}
		float shared[WIDTH];
		for (int i = 2; i <= WIDTH; i++) shared[i - 1] = share(choices[node.l], choices[node.r], i, c.left[i - 1]);
		float wide = area * NODE_COST + shared[WIDTH - 1];
		c.leaf = node.size <= MAX_LEAF_TRIANGLES && leaf <= wide;
		c.cost[0] = c.leaf ? leaf : wide;
		for (int i = 2; i <= WIDTH; i++) c.cost[i - 1] = std::min(c.cost[0], shared[i - 1]);
	}
}

// S(n, count), from n's children's choices l and r; `left` becomes the left child's share.
float Sah_Collapse::share(const Choice& l, const Choice& r, int count, uint8_t& left) {
	float best = INFINITY;
	for (int k = 1; k < count; k++) {
		float cost = l.cost[k - 1] + r.cost[count - k - 1];
		if (k == 1 || cost < best) best = cost, left = uint8_t(k);
	}
	return best;
}

// Appends the children that binary node n's subtree becomes with at most `count` of them.
void Sah_Collapse::append_children(size_t n, int count, std::vector<Wide_Child>& out) const {
	const Choice& c = choices[n];
	if (!(c.cost[count - 1] < c.cost[0])) { // one child is as cheap as any share (a leaf: always)
		out.push_back(Wide_Child{n, c.leaf});
		return;
	}
	int left = c.left[count - 1];
	append_children(bvh.nodes[n].l, left, out);
	append_children(bvh.nodes[n].r, count - left, out);
}

std::vector<Wide_Child> Sah_Collapse::children(size_t binary) const {
	const auto& node = bvh.nodes[binary];
	if (node.is_leaf()) return {Wide_Child{binary, true}};
	std::vector<Wide_Child> out;
	int left = choices[binary].left[WIDTH - 1];
	append_children(node.l, left, out);
	append_children(node.r, WIDTH - left, out);
	return out;
}

float Sah_Collapse::cost() const {
	if (bvh.nodes.empty()) return 0.0f;
	const auto& root = bvh.nodes[bvh.root_idx];
	float area = area_of(root.bbox);
	// The root is always a wide node (a leaf root its single child).
	uint8_t left = 0;
	float below = root.is_leaf() ? choices[bvh.root_idx].cost[0]
	                             : share(choices[root.l], choices[root.r], WIDTH, left);
	return area > 0.0f ? (area * NODE_COST + below) / area : 0.0f;
}

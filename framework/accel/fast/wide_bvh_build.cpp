// The fast accelerator's build: a finished BVH folded into wide nodes, a mesh's leaves packed.
#include "instance.h"
#include "sah_collapse.h"
#include "tri_mesh.h"
#include "wide_bvh.h"

#include <algorithm>
#include <iterator>
#include <optional>
#include <type_traits>

namespace {

// Appends the packs of triangles[start, start + size) to wide.triangle_packs, and their normals to
// wide.pack_normals; returns the index of the first.
uint32_t pack_triangles(const std::vector<Triangle>& triangles, size_t start, size_t size, Wide_BVH& wide) {
	std::vector<Triangle_Pack>& packs = wide.triangle_packs;
	uint32_t first = uint32_t(packs.size());
	for (size_t i = 0; i < size; i++) {
		if (i % 4 == 0) {
			packs.emplace_back();
			std::fill(std::begin(packs.back().index), std::end(packs.back().index), ~0u);
			wide.pack_normals.emplace_back();
		}
		Triangle_Pack& pack = packs.back();
		const Triangle& tri = triangles[start + i];
		Vec3 e1 = tri.v1.position - tri.v0.position, e2 = tri.v2.position - tri.v0.position;
		for (int axis = 0; axis < 3; axis++) {
			pack.v0[axis][i % 4] = tri.v0.position[axis];
			pack.e1[axis][i % 4] = e1[axis];
			pack.e2[axis][i % 4] = e2[axis];
		}
		pack.index[i % 4] = uint32_t(start + i);
		Vec3* normals = wide.pack_normals.back().normal[i % 4];
		normals[0] = tri.v0.normal, normals[1] = tri.v1.normal, normals[2] = tri.v2.normal;
	}
	return first;
}

// The children of binary node `binary` that a wide node takes: its two children, then, until there
// are Wide_Node::WIDTH or only leaves, the interior child of largest surface area (the one a ray
// most likely enters) opened into its two. A leaf root is its own single child. (A BVH<Triangle>'s
// wide nodes take the children of least SAH cost instead: sah_collapse.h.)
template<typename Node> std::vector<Wide_Child> largest_first(const std::vector<Node>& nodes, size_t binary) {
	if (nodes[binary].is_leaf()) return {Wide_Child{binary, true}};
	std::vector<size_t> children{nodes[binary].l, nodes[binary].r};
	while (children.size() < size_t(Wide_Node::WIDTH)) {
		auto largest = children.end();
		for (auto c = children.begin(); c != children.end(); c++) {
			if (!nodes[*c].is_leaf() &&
			    (largest == children.end() || nodes[*c].bbox.surface_area() > nodes[*largest].bbox.surface_area()))
				largest = c;
		}
		if (largest == children.end()) break; // only leaves
		size_t opened = *largest;
		*largest = nodes[opened].l;
		children.push_back(nodes[opened].r);
	}
	std::vector<Wide_Child> wide;
	for (size_t c : children) wide.push_back(Wide_Child{c, nodes[c].is_leaf()});
	return wide;
}

} // namespace

// From the root down, each wide node takes the children that Sah_Collapse (a mesh's tree) or
// largest_first (a scene's) chooses, the largest box in the first slot; a leaf is a child slot with
// count > 0.
template<typename Primitive> Wide_BVH widen(const BVH<Primitive>& bvh) {
	Wide_BVH wide;
	if (bvh.primitives.empty() || bvh.nodes.empty()) return wide;
	wide.nodes.resize(1);
	std::optional<Sah_Collapse> collapse;
	if constexpr (std::is_same_v<Primitive, Triangle>) collapse.emplace(bvh);
	std::vector<std::pair<size_t, size_t>> todo{{bvh.root_idx, 0}}; // binary node -> its wide node
	while (!todo.empty()) {
		auto [binary, index] = todo.back();
		todo.pop_back();
		std::vector<Wide_Child> children = collapse ? collapse->children(binary) : largest_first(bvh.nodes, binary);
		// The largest box first: after the child it crosses longest, an any-hit query enters the
		// children it hits in slot order, and the larger of two boxes a ray crosses more likely
		// holds what stops it. (A broken primitive's NaN area counts as 0, so that the order stays
		// an order.)
		auto area = [&](const Wide_Child& c) {
			float a = bvh.nodes[c.binary].bbox.surface_area();
			return a >= 0.0f ? a : 0.0f;
		};
		std::stable_sort(children.begin(), children.end(),
		                 [&](const Wide_Child& a, const Wide_Child& b) { return area(a) > area(b); });
		Wide_Node node;
		for (int slot = 0; slot < Wide_Node::WIDTH; slot++) { // unused slots: an empty box and UNUSED_SLOT
			BBox box = slot < int(children.size()) ? bvh.nodes[children[slot].binary].bbox : BBox{};
			node.min_x[slot] = box.min.x, node.min_y[slot] = box.min.y, node.min_z[slot] = box.min.z;
			node.max_x[slot] = box.max.x, node.max_y[slot] = box.max.y, node.max_z[slot] = box.max.z;
			node.first[slot] = Wide_Node::UNUSED_SLOT, node.count[slot] = 0;
			if (slot >= int(children.size())) continue;
			const auto& child = bvh.nodes[children[slot].binary];
			if (children[slot].leaf) {
				node.first[slot] = uint32_t(child.start);
				if constexpr (std::is_same_v<Primitive, Triangle>)
					node.first[slot] = pack_triangles(bvh.primitives, child.start, child.size, wide);
				node.count[slot] = uint32_t(child.size);
			} else {
				node.first[slot] = uint32_t(wide.nodes.size());
				wide.nodes.emplace_back();
				todo.push_back({children[slot].binary, wide.nodes.size() - 1});
			}
		}
		wide.nodes[index] = node;
	}
	// The vectors grew by doubling: give back the room they do not use.
	wide.nodes.shrink_to_fit();
	wide.triangle_packs.shrink_to_fit();
	wide.pack_normals.shrink_to_fit();
	wide.fits_in_cache = wide.bytes() <= 32 * 1024;
	return wide;
}

template Wide_BVH widen(const BVH<Triangle>&);
template Wide_BVH widen(const BVH<Instance>&);

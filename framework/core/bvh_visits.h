#pragma once
// Counting BVH work for the heat-map view: the number of nodes whose boxes overlap a ray's
// segment up to its closest hit. An ideal front-to-back traversal visits about these nodes, so the
// count shows the quality of a tree, whoever built it.
#include "instance.h"

template<typename Primitive, typename Leaf_Visitor>
size_t count_overlapped_nodes(const BVH<Primitive>& bvh, const Ray& ray, Leaf_Visitor&& leaf_visitor) {
	if (bvh.nodes.empty()) return 0;
	size_t count = 0;
	std::vector<size_t> stack{bvh.root_idx};
	while (!stack.empty()) {
		const auto& node = bvh.nodes[stack.back()];
		stack.pop_back();
		Vec2 times = ray.dist_bounds;
		if (!node.bbox.hit(ray, times)) continue;
		count++;
		if (node.is_leaf()) {
			for (size_t i = node.start; i < node.start + node.size; i++) count += leaf_visitor(bvh.primitives[i]);
		} else {
			stack.push_back(node.l);
			stack.push_back(node.r);
		}
	}
	return count;
}

// Nodes of the scene's top-level BVH and of the mesh BVHs inside it.
inline size_t count_overlapped_nodes(const BVH<Instance>& scene_bvh, Ray ray, float closest_hit) {
	ray.dist_bounds.y = std::min(ray.dist_bounds.y, closest_hit);
	return count_overlapped_nodes(scene_bvh, ray, [&](const Instance& instance) -> size_t {
		auto mesh = std::get_if<Tri_Mesh>(&instance.shape);
		if (!mesh) return 0;
		Ray local(transform_point(instance.to_local, ray.point), transform_direction(instance.to_local, ray.dir),
		          ray.dist_bounds);
		return count_overlapped_nodes(mesh->bvh, local, [](const Triangle&) { return size_t(0); });
	});
}

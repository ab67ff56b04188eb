#include "bench_stats.h"
#include "bvh_visits.h"

double sah_cost(const BVH<Triangle>& bvh) {
	if (bvh.nodes.empty()) return 0.0;
	double root_area = bvh.nodes[bvh.root_idx].bbox.surface_area(), cost = 0.0;
	for (const auto& node : bvh.nodes) {
		double fraction = node.bbox.surface_area() / root_area;
		cost += node.is_leaf() ? fraction * double(node.size) : fraction;
	}
	return cost;
}

size_t bvh_bytes(const BVH<Triangle>& bvh) {
	return bvh.nodes.capacity() * sizeof(bvh.nodes[0]) + bvh.primitives.capacity() * sizeof(Triangle);
}

Visit_Counts visit_counts(const BVH<Triangle>& bvh, const std::vector<Ray>& rays, const std::vector<float>& hits) {
	Visit_Counts counts;
	for (size_t i = 0; i < rays.size(); i++) {
		Ray ray = rays[i];
		ray.dist_bounds.y = std::min(ray.dist_bounds.y, hits[i]);
		size_t triangles = 0;
		counts.nodes += double(count_overlapped_nodes(bvh, ray, [&](const Triangle&) {
			triangles++;
			return size_t(0);
		}));
		counts.triangles += double(triangles);
	}
	counts.nodes /= double(rays.size());
	counts.triangles /= double(rays.size());
	return counts;
}

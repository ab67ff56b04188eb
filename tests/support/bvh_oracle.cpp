#include "bvh_oracle.h"

#include <algorithm>
#include <cmath>

namespace oracle {
namespace {

double area(const BBox& box) {
	return double(box.surface_area());
}

struct Builder {
	const std::vector<BBox>& boxes;
	size_t max_leaf_size;
	int buckets;
	Tree tree;

	Vec3 centroid(size_t prim) const {
		return boxes[prim].center();
	}

	int bucket(size_t prim, const BBox& centroids, int axis) const {
		double lo = centroids.min[axis], hi = centroids.max[axis];
		double k = std::floor(buckets * (double(centroid(prim)[axis]) - lo) / (hi - lo));
		return int(std::clamp(k, 0.0, double(buckets - 1)));
	}

	// Builds the subtree over order[begin, end) and returns its node index.
	long build(size_t begin, size_t end) {
		long idx = long(tree.nodes.size());
		tree.nodes.push_back(Node{BBox{}, begin, end, -1, -1});
		BBox box, centroids;
		for (size_t i = begin; i < end; i++) {
			box.enclose(boxes[tree.order[i]]);
			centroids.enclose(centroid(tree.order[i]));
		}
		tree.nodes[idx].box = box;
		if (end - begin <= max_leaf_size) return idx;

		// Cheapest bucket boundary over the three axes, cost S_A N_A + S_B N_B.
		int best_axis = -1, best_split = 0;
		double best_cost = INFINITY;
		for (int axis = 0; axis < 3; axis++) {
			if (!(centroids.max[axis] > centroids.min[axis])) continue;
			std::vector<BBox> bucket_box(buckets);
			std::vector<size_t> count(buckets, 0);
			for (size_t i = begin; i < end; i++) {
				int b = bucket(tree.order[i], centroids, axis);
				bucket_box[b].enclose(boxes[tree.order[i]]);
				count[b]++;
			}
			for (int split = 0; split + 1 < buckets; split++) {
				BBox a, b;
				size_t na = 0, nb = 0;
				for (int k = 0; k < buckets; k++) {
					(k <= split ? a : b).enclose(bucket_box[k]);
					(k <= split ? na : nb) += count[k];
				}
				if (na == 0 || nb == 0) continue;
				double cost = area(a) * double(na) + area(b) * double(nb);
				if (cost < best_cost) best_cost = cost, best_axis = axis, best_split = split;
			}
		}
		if (best_axis < 0) return idx; // all centroids coincide

		auto first = tree.order.begin();
		size_t mid = size_t(std::stable_partition(first + long(begin), first + long(end), [&](size_t prim) {
			                    return bucket(prim, centroids, best_axis) <= best_split;
		                    }) - first);
		long left = build(begin, mid);
		long right = build(mid, end);
		tree.nodes[idx].left = left;
		tree.nodes[idx].right = right;
		return idx;
	}
};

} // namespace

Tree build_binned_sah(const std::vector<BBox>& boxes, size_t max_leaf_size, int buckets) {
	Builder builder{boxes, std::max<size_t>(max_leaf_size, 1), buckets, Tree{}};
	for (size_t i = 0; i < boxes.size(); i++) builder.tree.order.push_back(i);
	if (!boxes.empty()) builder.build(0, boxes.size());
	return std::move(builder.tree);
}

double sah_cost(const Tree& tree, const std::vector<BBox>& boxes) {
	if (tree.nodes.empty()) return 0.0;
	double total = 0.0;
	for (const Node& node : tree.nodes) {
		BBox box;
		for (size_t i = node.begin; i < node.end; i++) box.enclose(boxes[tree.order[i]]);
		total += area(box) * (node.is_leaf() ? double(node.end - node.begin) : 1.0);
	}
	BBox root;
	for (const BBox& b : boxes) root.enclose(b);
	return total / area(root);
}

bool slab(const BBox& box, const Ray& ray, float& t0, float& t1) {
	for (int axis = 0; axis < 3; axis++) {
		float o = ray.point[axis], d = ray.dir[axis];
		if (d == 0.0f) {
			// Parallel to this slab: inside it for every t, or for none.
			if (!(box.min[axis] <= o && o <= box.max[axis])) return false;
			continue;
		}
		float a = (box.min[axis] - o) / d, b = (box.max[axis] - o) / d;
		t0 = std::max(t0, std::min(a, b));
		t1 = std::min(t1, std::max(a, b));
	}
	return t0 <= t1;
}

Trace traverse(const Tree& tree, const Ray& ray, const std::function<Trace(size_t, const Ray&)>& hit_primitive) {
	Trace closest;
	if (tree.nodes.empty()) return closest;
	Ray r = ray;
	std::vector<std::pair<long, float>> stack; // (node, entry t)
	float t0 = r.dist_bounds.x, t1 = r.dist_bounds.y;
	if (slab(tree.nodes[0].box, r, t0, t1)) stack.push_back({0, t0});
	while (!stack.empty()) {
		auto [idx, t_enter] = stack.back();
		stack.pop_back();
		if (t_enter > r.dist_bounds.y) continue;
		const Node& node = tree.nodes[size_t(idx)];
		if (node.is_leaf()) {
			for (size_t i = node.begin; i < node.end; i++) {
				Trace t = hit_primitive(tree.order[i], r);
				if (t.hit && (!closest.hit || t.distance < closest.distance)) closest = t;
				if (closest.hit) r.dist_bounds.y = closest.distance;
			}
			continue;
		}
		float a0 = r.dist_bounds.x, a1 = r.dist_bounds.y, b0 = a0, b1 = a1;
		bool hit_a = slab(tree.nodes[size_t(node.left)].box, r, a0, a1);
		bool hit_b = slab(tree.nodes[size_t(node.right)].box, r, b0, b1);
		std::pair<long, float> near{node.left, a0}, far{node.right, b0};
		bool hit_near = hit_a, hit_far = hit_b;
		if (hit_b && (!hit_a || b0 < a0)) std::swap(near, far), std::swap(hit_near, hit_far);
		// Push the farther child first so that the nearer one is visited next.
		if (hit_far) stack.push_back(far);
		if (hit_near) stack.push_back(near);
	}
	return closest;
}

} // namespace oracle

// Task 3: bounding volume hierarchy. Handout: handouts/task3_bvh.md
#include "bvh.h"
#include "instance.h"
#include "tri_mesh.h"

#include <algorithm>
#include <array>

namespace {

// A ray prepared for many slab tests: the reciprocal direction is computed once per ray.
struct Slab_Ray {
	explicit Slab_Ray(const Ray& ray) : point(ray.point), inv_dir(1.0f / ray.dir) {
	}
	Vec3 point;
	Vec3 inv_dir; // +-inf where a direction component is +-0
};

// Slab test (handout §3.1). On each axis the ray lies between the planes min and max for t in
// [(min - o) / d, (max - o) / d], ends swapped when d < 0; the box is hit where all three slabs
// and `times` overlap. Comparisons are <=, so flat boxes (min == max) are hit.
bool slab_test(const BBox& box, const Slab_Ray& ray, Vec2& times) {
	float t_enter = times.x, t_exit = times.y;
	for (int axis = 0; axis < 3; axis++) {
		float t_near = (box.min[axis] - ray.point[axis]) * ray.inv_dir[axis];
		float t_far = (box.max[axis] - ray.point[axis]) * ray.inv_dir[axis];
		if (ray.inv_dir[axis] < 0.0f) std::swap(t_near, t_far);
		// When d = 0 and the origin lies on a plane, 0 * inf = NaN: a NaN fails the comparison,
		// so it leaves the interval unchanged (the ray runs inside that plane).
		t_enter = t_near > t_enter ? t_near : t_enter;
		t_exit = t_far < t_exit ? t_far : t_exit;
	}
	if (!(t_enter <= t_exit)) return false;
	times = Vec2{t_enter, t_exit};
	return true;
}

// Binned SAH (handout §3.2): the primitives' centroids are binned into this many buckets per axis.
constexpr int BUCKETS = 16;

// What the build needs to know about a primitive, computed once.
struct Build_Item {
	BBox bbox;
	Vec3 centroid;
	size_t index; // position in the input vector
};

struct Bucket {
	BBox bbox;
	size_t count = 0;
};

struct Split {
	int axis = -1;  // -1: no split separates the primitives
	int bucket = 0; // buckets 0..bucket go left
	float cost = INF_F;
};

BBox bounds(const Build_Item* begin, const Build_Item* end) {
	BBox box;
	for (const Build_Item* item = begin; item != end; item++) box.enclose(item->bbox);
	return box;
}

BBox centroid_bounds(const Build_Item* begin, const Build_Item* end) {
	BBox box;
	for (const Build_Item* item = begin; item != end; item++) box.enclose(item->centroid);
	return box;
}

// The buckets of one axis: b = min(B - 1, floor(B (c - c_min) / (c_max - c_min))) (handout §3.2),
// with the scale B / (c_max - c_min) computed once per axis and node.
struct Bucketing {
	Bucketing(const BBox& centroids, int axis)
		: axis(axis), min(centroids.min[axis]), scale(BUCKETS / (centroids.max[axis] - centroids.min[axis])) {
	}
	int operator()(Vec3 centroid) const {
		return std::min(int((centroid[axis] - min) * scale), BUCKETS - 1);
	}
	int axis;
	float min, scale;
};

// The cheapest split between buckets over all three axes. With C_trav = C_isect = 1, a split costs
// C = 1 + (S_A N_A + S_B N_B) / S_N; we minimize S_A N_A + S_B N_B, which orders splits the same.
Split best_split(const Build_Item* begin, const Build_Item* end, const BBox& centroids) {
	Split best;
	for (int axis = 0; axis < 3; axis++) {
		if (!(centroids.max[axis] > centroids.min[axis])) continue; // all centroids in one plane
		std::array<Bucket, BUCKETS> buckets;
		Bucketing bucket_of(centroids, axis);
		for (const Build_Item* item = begin; item != end; item++) {
			Bucket& b = buckets[bucket_of(item->centroid)];
			b.bbox.enclose(item->bbox);
			b.count++;
		}
		// Sweep from the right for the right side of every split, then from the left.
		std::array<Bucket, BUCKETS - 1> right; // right[k]: buckets k+1 .. BUCKETS-1
		Bucket side;
		for (int k = BUCKETS - 2; k >= 0; k--) {
			side.bbox.enclose(buckets[k + 1].bbox);
			side.count += buckets[k + 1].count;
			right[k] = side;
		}
		Bucket left;
		for (int k = 0; k < BUCKETS - 1; k++) {
			left.bbox.enclose(buckets[k].bbox);
			left.count += buckets[k].count;
			if (left.count == 0 || right[k].count == 0) continue;
			float cost = left.bbox.surface_area() * left.count + right[k].bbox.surface_area() * right[k].count;
			// (The first candidate is taken even if its cost is inf: a primitive with an infinite box
			// must not stop the build.)
			if (best.axis < 0 || cost < best.cost) best = Split{axis, k, cost};
		}
	}
	return best;
}

} // namespace

bool BBox::hit(const Ray& ray, Vec2& times) const {
	return slab_test(*this, Slab_Ray(ray), times);
}

template<typename Primitive> void BVH<Primitive>::build(std::vector<Primitive>&& prims, size_t max_leaf_size) {
	nodes.clear();
	max_leaf_size = std::max<size_t>(max_leaf_size, 1);
	std::vector<Build_Item> items;
	items.reserve(prims.size());
	for (size_t i = 0; i < prims.size(); i++) {
		BBox box = prims[i].bbox();
		// A broken primitive (NaN or infinite vertices) gets a stand-in centroid, so that it
		// cannot spoil the bucket bounds of the others.
		Vec3 centroid = is_finite(box.center()) ? box.center() : Vec3{0.0f};
		items.push_back(Build_Item{box, centroid, i});
	}

	// Split nodes until they are small enough: a node covers items[start, start + size).
	Build_Item* all = items.data();
	root_idx = new_node(bounds(all, all + items.size()), 0, items.size());
	std::vector<size_t> todo{root_idx};
	while (!todo.empty()) {
		size_t idx = todo.back();
		todo.pop_back();
		Build_Item* begin = all + nodes[idx].start;
		Build_Item* end = begin + nodes[idx].size;
		nodes[idx].l = nodes[idx].r = idx; // a leaf unless split below

		if (nodes[idx].size <= max_leaf_size) continue;
		BBox centroids = centroid_bounds(begin, end);
		Split split = best_split(begin, end, centroids);
		if (split.axis < 0) continue; // all centroids coincide: nothing can separate them

		Bucketing bucket_of(centroids, split.axis);
		Build_Item* mid = std::partition(begin, end, [&](const Build_Item& item) {
			return bucket_of(item.centroid) <= split.bucket;
		});
		size_t l = new_node(bounds(begin, mid), size_t(begin - all), size_t(mid - begin));
		size_t r = new_node(bounds(mid, end), size_t(mid - all), size_t(end - mid));
		nodes[idx].l = l;
		nodes[idx].r = r;
		todo.push_back(r);
		todo.push_back(l);
	}

	// Store the primitives in the order the leaves cover them.
	primitives.clear();
	primitives.reserve(items.size());
	for (const Build_Item& item : items) primitives.push_back(std::move(prims[item.index]));
}

template<typename Primitive> Trace BVH<Primitive>::hit(const Ray& ray) const {
	// Front to back (handout §3.3): an explicit stack of nodes still to visit, each with the t at
	// which the ray enters its box. The nearer child is pushed last, so it is visited first.
	struct Entry {
		size_t node;
		float t_enter;
	};
	// One stack per thread, reused by every ray, so that a ray allocates nothing. (BVH<Triangle>
	// and BVH<Instance> each have their own: a mesh traversed from inside the scene's traversal
	// does not disturb it.)
	thread_local std::vector<Entry> stack;
	stack.clear();

	Trace closest;
	Ray r = ray; // r.dist_bounds.y shrinks to the closest hit found so far
	Slab_Ray slab_ray(ray);
	Vec2 times = r.dist_bounds;
	if (nodes.empty() || !slab_test(nodes[root_idx].bbox, slab_ray, times)) return closest;
	stack.push_back(Entry{root_idx, times.x});

	while (!stack.empty()) {
		Entry entry = stack.back();
		stack.pop_back();
		if (entry.t_enter > r.dist_bounds.y) continue; // a closer hit was found since it was pushed
		const Node& node = nodes[entry.node];
		if (node.is_leaf()) {
			for (size_t i = node.start; i < node.start + node.size; i++) {
				closest = Trace::min(closest, primitives[i].hit(r));
				if (closest.hit) r.dist_bounds.y = closest.distance;
			}
			continue;
		}
		Vec2 times_l = r.dist_bounds, times_r = r.dist_bounds;
		bool hit_l = slab_test(nodes[node.l].bbox, slab_ray, times_l);
		bool hit_r = slab_test(nodes[node.r].bbox, slab_ray, times_r);
		if (hit_l && hit_r) {
			bool left_first = times_l.x <= times_r.x;
			stack.push_back(left_first ? Entry{node.r, times_r.x} : Entry{node.l, times_l.x});
			stack.push_back(left_first ? Entry{node.l, times_l.x} : Entry{node.r, times_r.x});
		} else if (hit_l) {
			stack.push_back(Entry{node.l, times_l.x});
		} else if (hit_r) {
			stack.push_back(Entry{node.r, times_r.x});
		}
	}
	return closest;
}

// The framework builds BVHs of triangles (inside meshes) and of scene objects.
template class BVH<Triangle>;
template class BVH<Instance>;

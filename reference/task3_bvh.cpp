// Task 3: bounding volume hierarchy. Handout: handouts/task3_bvh.md
#include "bvh.h"
#include "instance.h"
#include "tri_mesh.h"

#include <algorithm>
#include <array>

namespace {

// A ray prepared for many slab tests: the reciprocal direction and its signs are computed once per ray.
struct Slab_Ray {
	explicit Slab_Ray(const Ray& ray) : point(ray.point), inv_dir(1.0f / ray.dir) {
		for (int axis = 0; axis < 3; axis++) negative[axis] = inv_dir[axis] < 0.0f;
	}
	Vec3 point;
	Vec3 inv_dir; // +-inf where a direction component is +-0
	bool negative[3];
};

// One slab of the slab test: narrows [t_enter, t_exit] to where the ray lies between the planes lo
// and hi of one axis, t in [(lo - o) / d, (hi - o) / d], ends swapped when d < 0. When d = 0 and the
// origin lies on a plane, 0 * inf = NaN: a NaN fails the comparison, so it leaves the interval
// unchanged (the ray runs inside that plane).
[[gnu::always_inline]] inline void narrow(float lo, float hi, float point, float inv_dir, bool negative,
                                          float& t_enter, float& t_exit) {
	float t_lo = (lo - point) * inv_dir, t_hi = (hi - point) * inv_dir;
	float t_near = negative ? t_hi : t_lo, t_far = negative ? t_lo : t_hi;
	t_enter = t_near > t_enter ? t_near : t_enter;
	t_exit = t_far < t_exit ? t_far : t_exit;
}

// Slab test (handout §3.1): the box is hit where all three slabs and `times` overlap. Comparisons
// are <=, so flat boxes (min == max) are hit. Written out per axis and inlined, since traversal
// spends much of its time here (it was a third of the time as an out-of-line loop).
[[gnu::always_inline]] inline bool slab_test(Vec3 min, Vec3 max, const Slab_Ray& ray, Vec2& times) {
	float t_enter = times.x, t_exit = times.y;
	narrow(min.x, max.x, ray.point.x, ray.inv_dir.x, ray.negative[0], t_enter, t_exit);
	narrow(min.y, max.y, ray.point.y, ray.inv_dir.y, ray.negative[1], t_enter, t_exit);
	narrow(min.z, max.z, ray.point.z, ray.inv_dir.z, ray.negative[2], t_enter, t_exit);
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
	int axis = -1; // -1: no split separates the primitives
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

// The bucket of a centroid along `axis`.
int bucket_of(Vec3 centroid, const BBox& centroids, int axis) {
	float f = BUCKETS * (centroid[axis] - centroids.min[axis]) / (centroids.max[axis] - centroids.min[axis]);
	return std::min(int(f), BUCKETS - 1);
}

// The cheapest split between buckets over all three axes. With C_trav = C_isect = 1, a split costs
// C = 1 + (S_A N_A + S_B N_B) / S_N; we minimize S_A N_A + S_B N_B, which orders splits the same.
Split best_split(const Build_Item* begin, const Build_Item* end, const BBox& centroids) {
	Split best;
	for (int axis = 0; axis < 3; axis++) {
		if (!(centroids.max[axis] > centroids.min[axis])) continue; // all centroids in one plane
		std::array<Bucket, BUCKETS> buckets;
		for (const Build_Item* item = begin; item != end; item++) {
			Bucket& b = buckets[bucket_of(item->centroid, centroids, axis)];
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

// --- Traversal data (bench/README.md). The tree above is the lab's; build() then copies it into
// BVH::flat_pairs, which hit() traverses. Measured with bench/bvh_bench (Stanford bunny, one thread,
// ratio to Embree in the same run, medians of 5; primary / incoherent / occlusion): the traversal of
// `nodes` with a std::vector stack 0.33 / 0.23 / 0.17; with 32-byte nodes, siblings in one cache
// line, the slab test inlined and a stack indexed in place 0.55 / 0.30 / 0.24. (Precomputed
// triangles, testing only t and making one Trace at the end, bought nothing measurable on top, so
// they were left out; so was prefetching the far child.)

// Copies the tree into pairs of flat nodes, depth first: the root alone in pair 0, then the
// children of each interior node side by side in a pair of their own.
template<typename Node, typename Flat_Pair>
std::vector<Flat_Pair> flatten(const std::vector<Node>& nodes, size_t root_idx) {
	std::vector<Flat_Pair> pairs(1);
	pairs.reserve(nodes.size() / 2 + 1);
	struct Todo {
		size_t node, pair;
		int child;
	};
	std::vector<Todo> todo{{root_idx, 0, 0}};
	while (!todo.empty()) {
		Todo item = todo.back();
		todo.pop_back();
		const Node& node = nodes[item.node];
		auto& out = pairs[item.pair].child[item.child];
		out = {node.bbox.min, uint32_t(node.start), node.bbox.max, uint32_t(node.size)};
		if (node.is_leaf()) continue;
		out.first = uint32_t(pairs.size()), out.count = 0; // (`out` is not used after the next line)
		pairs.emplace_back();
		todo.push_back(Todo{node.r, pairs.size() - 1, 1});
		todo.push_back(Todo{node.l, pairs.size() - 1, 0});
	}
	return pairs;
}

} // namespace

bool BBox::hit(const Ray& ray, Vec2& times) const {
	return slab_test(min, max, Slab_Ray(ray), times);
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

		Build_Item* mid = std::partition(begin, end, [&](const Build_Item& item) {
			return bucket_of(item.centroid, centroids, split.axis) <= split.bucket;
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

	flat_pairs.clear();
	if (!primitives.empty()) flat_pairs = flatten<Node, Flat_Pair>(nodes, root_idx);
}

namespace {

// Front to back (handout §3.3) over flat_pairs: go down into the nearer child and keep the farther
// one on a stack, with the t at which the ray enters its box. The closest-hit query (hit()) shrinks
// the ray to each hit it finds; the any-hit query (occluded()) returns at the first.
template<bool ANY_HIT, typename Primitive> Trace traverse(const BVH<Primitive>& bvh, const Ray& ray) {
	using Flat_Node = typename BVH<Primitive>::Flat_Node;
	struct Entry {
		const Flat_Node* node;
		float t_enter;
	};
	// One stack per thread and instantiation, reused by every ray (so a mesh traversed from inside
	// the scene's traversal does not disturb it). It only grows: a push checks the size, a pop is
	// an index decrement.
	thread_local std::vector<Entry> stack(64);
	size_t top = 0;

	Ray r = ray; // r.dist_bounds.y shrinks to the closest hit found so far
	Slab_Ray slab_ray(ray);
	Trace closest;
	Vec2 times = r.dist_bounds;
	if (bvh.flat_pairs.empty()) return closest;
	const Flat_Node* node = &bvh.flat_pairs[0].child[0];
	if (!slab_test(node->min, node->max, slab_ray, times)) return closest;

	while (true) {
		if (node->count > 0) {
			for (size_t i = node->first; i < node->first + node->count; i++) {
				closest = Trace::min(closest, bvh.primitives[i].hit(r));
				if (closest.hit) {
					if constexpr (ANY_HIT) return closest;
					r.dist_bounds.y = closest.distance;
				}
			}
		} else {
			const Flat_Node *left = &bvh.flat_pairs[node->first].child[0], *right = left + 1;
			Vec2 times_l = r.dist_bounds, times_r = r.dist_bounds;
			bool hit_l = slab_test(left->min, left->max, slab_ray, times_l);
			bool hit_r = slab_test(right->min, right->max, slab_ray, times_r);
			if (hit_l && hit_r) {
				bool left_first = times_l.x <= times_r.x;
				if (top == stack.size()) stack.resize(2 * top);
				stack[top++] = left_first ? Entry{right, times_r.x} : Entry{left, times_l.x};
				node = left_first ? left : right;
				continue;
			}
			if (hit_l || hit_r) {
				node = hit_l ? left : right;
				continue;
			}
		}
		// Pop the nearest pending node that still starts before the closest hit.
		while (top > 0 && stack[top - 1].t_enter > r.dist_bounds.y) top--;
		if (top == 0) break;
		node = stack[--top].node;
	}
	return closest;
}

} // namespace

template<typename Primitive> Trace BVH<Primitive>::hit(const Ray& ray) const {
	return traverse<false>(*this, ray);
}

template<typename Primitive> bool BVH<Primitive>::occluded(const Ray& ray) const {
	return traverse<true>(*this, ray).hit;
}

// The framework builds BVHs of triangles (inside meshes) and of scene objects.
template class BVH<Triangle>;
template class BVH<Instance>;

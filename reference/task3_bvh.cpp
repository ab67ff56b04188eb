// Task 3: bounding volume hierarchy. Handout: handouts/task3_bvh.md
#include "bvh.h"
#include "instance.h"
#include "tri_mesh.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <iterator>
#include <type_traits>

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
// are <=, so flat boxes (min == max) are hit. (BBox::hit; traversal tests four boxes at once the
// same way, hit_children below.)
inline bool slab_test(Vec3 min, Vec3 max, const Slab_Ray& ray, Vec2& times) {
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

// The buckets of one axis: [min, max] of the centroids cut into BUCKETS equal parts. (One
// division per axis and node, not per primitive: the build bins every primitive three times.)
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

// --- Traversal data (bench/README.md). The tree above is the lab's binary tree; build() then folds
// it into BVH::wide_nodes, eight children to a node, and packs each leaf's triangles four at a time
// (BVH::triangle_packs); hit() traverses those. Measured with bench/bvh_bench (one thread, ratio to
// Embree's rtcIntersect1 in the same run, medians; primary / incoherent / occlusion), Stanford bunny:
// - `nodes` with a std::vector stack:                                         0.33 / 0.23 / 0.17
// - 32-byte nodes, siblings in one cache line, inlined slab test, own stack:   0.57 / 0.29 / 0.20
// - occlusion rays as an any-hit query (BVH::occluded) instead of closest hit:  0.62 / 0.29 / 0.25
// - four children to a node, their boxes tested at once:                       0.71 / 0.33 / 0.29
// - leaf triangles in packs of four, tested at once as a filter:               0.78 / 0.34 / 0.29
// - eight children to a node (two 4-wide tests), a third fewer node loads:    0.87 / 0.42 / 0.31
//   (the same day, alternating runs with the 4-wide nodes: 0.62 / 0.35 / 0.28 against 0.61 /
//   0.34 / 0.26 on the bunny, and 0.53 / 0.52 / 0.44 against 0.52 / 0.50 / 0.43 on large.json:
//   a few percent on incoherent and occlusion rays, within the machine's noise on primary ones)
// - the children hit ordered without a sort when one or two are hit (most nodes), unused slots
//   masked in the vector test; alternating runs with the step above, 5 on the bunny:
//   0.67 / 0.44 / 0.35 against 0.62 / 0.39 / 0.30 (large.json, 2 runs: 0.56 / 0.52 / 0.43
//   against 0.55 / 0.55 / 0.46, within its noise)
// - the packs of all leaves a node's test finds prefetched at once; alternating runs with the step
//   above, 4 on the bunny: 0.67 / 0.48 / 0.35 against 0.67 / 0.43 / 0.35 (large.json, 2 runs:
//   0.60 / 0.61 / 0.49 against 0.54 / 0.55 / 0.49)
// - occluded(): the children hit taken in slot order, not nearest first; alternating runs with the
//   step above, 4 on the bunny: occlusion 0.45 against 0.36 (large.json, 1 run: 0.52 against 0.45)
// - packs that answer the hit: the pack test is Triangle::hit's arithmetic, lane by lane, so it
//   keeps the closest (t, triangle) itself and Triangle::hit runs once, on the winner, for the
//   record (its Triangle prefetched when it is found); alternating the two in one binary, 4 runs
//   on the bunny: 0.71 / 0.47 against 0.68 / 0.44 (primary / incoherent; large.json, 2 runs:
//   0.55 / 0.60 against 0.52 / 0.61)
// - occluded(): the pack's verdict ends the query without loading the Triangle (where it is
//   Triangle::hit's bit for bit: PACK_IS_EXACT); alternating runs, 3 on the bunny: occlusion 0.67
//   against 0.42 (large.json, 2 runs: 0.70 against 0.55)
// - a vector comparison's lanes read as a bit mask by one instruction (movmskps) instead of four
//   extracts; alternating runs, 3 on the bunny: 0.82 / 0.50 / 0.64 against 0.80 / 0.42 / 0.50
//   (large.json, 1 run: 0.63 / 0.62 / 0.70 against 0.58 / 0.65 / 0.74, within its noise)
// - for the closest hit, a leaf's triangles fetched along with its pack when a node's test finds
//   it (the node keeps each leaf's first triangle, a fifth cache line), not when the winner is
//   known: the final Triangle::hit's load had cost a quarter of a primary ray (large.json, a
//   record-less variant: 0.76 to 1.02 against 0.60 to 0.71); alternating runs, 6 on large.json:
//   0.80 / 0.59 / 0.65 against 0.75 / 0.62 / 0.65 (bunny, 3 runs: 0.98 / 0.56 / 0.60 against
//   1.01 / 0.54 / 0.63, within its noise)
// - the wider pack test only where the pack may round otherwise, the record written in place
//   (record()), the stack on the call stack; the old and new traversal timed in one binary:
//   primary +2 to +9 % (large.json +4 to +5 %), occlusion up to +13 %, incoherent within the noise
// The traversal waits on memory: most of its time goes to the first loads of a node and a pack.
// (Prefetching the far child bought nothing measurable; a leaf's pack, rarely cached, does.)
// Tried and dropped: leaves of up to eight triangles (two packs) in the wide tree, binary subtrees
// of five to eight folded into one leaf: bunny 0.68 / 0.50 / 0.50 against 0.74 / 0.45 / 0.44 (4
// runs), large.json 0.58 / 0.56 / 0.54 against 0.57 / 0.57 / 0.59 (3 runs); folded only where the
// SAH prefers it, within 2 % on large.json, timed in one process (bench/README.md).

// Four floats, handled by one SSE/NEON instruction per operation (GCC's and Clang's vector
// extension: arithmetic and comparisons work lane by lane; a comparison gives 0 or -1 per lane).
using Float4 = float __attribute__((vector_size(16)));
using Int4 = int32_t __attribute__((vector_size(16)));

// A bit per lane whose comparison holds (lane i: bit i); on x86 one instruction (movmskps) reads
// the four sign bits.
inline unsigned lane_bits(Int4 lanes) {
#if defined(__SSE__)
	return unsigned(__builtin_ia32_movmskps(Float4(lanes)));
#else
	return unsigned((lanes[0] & 1) | (lanes[1] & 2) | (lanes[2] & 4) | (lanes[3] & 8));
#endif
}

Float4 load4(const float* values) {
	Float4 v;
	std::memcpy(&v, values, sizeof v);
	return v;
}

// A wide node's slot without a child: its box is empty, but a ray with a NaN direction overlaps
// every box (see narrow()), so traversal checks this mark too.
constexpr uint32_t UNUSED_SLOT = ~0u;

// Slab test of a wide node's children, four at once (handout §3.1, as slab_test above, lane by
// lane): returns a bit per child hit within `bounds` (never an unused slot), and where the ray
// enters each child's box.
template<typename Wide_Node>
[[gnu::always_inline]] inline unsigned hit_children(const Wide_Node& node, const Slab_Ray& ray, Vec2 bounds,
                                                    float (&t_enter)[Wide_Node::WIDTH]) {
	const float* lo[3] = {node.min_x, node.min_y, node.min_z};
	const float* hi[3] = {node.max_x, node.max_y, node.max_z};
	unsigned mask = 0;
	for (int group = 0; group < Wide_Node::WIDTH; group += 4) { // four children at a time
		Float4 enter = Float4{} + bounds.x, exit = Float4{} + bounds.y;
		for (int axis = 0; axis < 3; axis++) {
			bool negative = ray.negative[axis];
			Float4 t_near = (load4((negative ? hi[axis] : lo[axis]) + group) - ray.point[axis]) * ray.inv_dir[axis];
			Float4 t_far = (load4((negative ? lo[axis] : hi[axis]) + group) - ray.point[axis]) * ray.inv_dir[axis];
			// As in narrow(): a NaN (0 * inf, a ray inside a slab's plane) fails the comparison and
			// leaves the interval unchanged.
			enter = t_near > enter ? t_near : enter;
			exit = t_far < exit ? t_far : exit;
		}
		std::memcpy(t_enter + group, &enter, sizeof enter);
		Int4 first;
		std::memcpy(&first, node.first + group, sizeof first);
		Int4 hit = (enter <= exit) & (first != Int4{} + int32_t(UNUSED_SLOT));
		mask |= lane_bits(hit) << group;
	}
	return mask;
}

// Appends the packs of triangles[start, start + size) to `packs`; returns the index of the first.
template<typename Triangle_Pack>
uint32_t pack_triangles(const std::vector<Triangle>& triangles, size_t start, size_t size,
                        std::vector<Triangle_Pack>& packs) {
	uint32_t first = uint32_t(packs.size());
	for (size_t i = 0; i < size; i++) {
		if (i % 4 == 0) {
			packs.emplace_back();
			std::fill(std::begin(packs.back().index), std::end(packs.back().index), ~0u);
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
	}
	return first;
}

// Folds the binary tree into nodes of up to Wide_Node::WIDTH (eight) children, from the root down: a
// wide node takes its binary node's two children, then opens the interior child of largest surface
// area (the one a ray most likely enters) into its two children, until it has eight or only leaves.
// A leaf of the binary tree stays a leaf, a child slot with count > 0.
template<typename Node, typename Wide_Node, typename Leaf_First>
std::vector<Wide_Node> widen(const std::vector<Node>& nodes, size_t root_idx, Leaf_First leaf_first) {
	std::vector<Wide_Node> wide(1);
	std::vector<std::pair<size_t, size_t>> todo{{root_idx, 0}}; // binary node -> its wide node
	while (!todo.empty()) {
		auto [binary, index] = todo.back();
		todo.pop_back();
		std::vector<size_t> children{binary}; // the root as a single child when it is a leaf
		if (!nodes[binary].is_leaf()) children = {nodes[binary].l, nodes[binary].r};
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
		Wide_Node node;
		for (int slot = 0; slot < Wide_Node::WIDTH; slot++) { // unused slots: an empty box and UNUSED_SLOT
			BBox box = slot < int(children.size()) ? nodes[children[slot]].bbox : BBox{};
			node.min_x[slot] = box.min.x, node.min_y[slot] = box.min.y, node.min_z[slot] = box.min.z;
			node.max_x[slot] = box.max.x, node.max_y[slot] = box.max.y, node.max_z[slot] = box.max.z;
			node.first[slot] = UNUSED_SLOT, node.count[slot] = 0, node.start[slot] = 0;
			if (slot >= int(children.size())) continue;
			const Node& child = nodes[children[slot]];
			if (child.is_leaf()) {
				node.first[slot] = leaf_first(child.start, child.size), node.count[slot] = uint32_t(child.size);
				node.start[slot] = uint32_t(child.start);
			} else {
				node.first[slot] = uint32_t(wide.size());
				wide.emplace_back();
				todo.push_back({children[slot], wide.size() - 1});
			}
		}
		wide[index] = node;
	}
	return wide;
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

	wide_nodes.clear();
	triangle_packs.clear();
	if (primitives.empty()) return;
	if constexpr (std::is_same_v<Primitive, Triangle>) {
		wide_nodes = widen<Node, Wide_Node>(nodes, root_idx, [&](size_t start, size_t size) {
			return pack_triangles(primitives, start, size, triangle_packs);
		});
	} else {
		wide_nodes = widen<Node, Wide_Node>(nodes, root_idx, [](size_t start, size_t) { return uint32_t(start); });
	}
	// The vectors grew by doubling: give back the room they do not use.
	nodes.shrink_to_fit();
	wide_nodes.shrink_to_fit();
	triangle_packs.shrink_to_fit();
}

namespace {

// Möller–Trumbore (handout §2.1) on the four triangles of a pack at once, with Triangle::hit's
// arithmetic (reference/task2_shapes.cpp: the same products and sums in the same order, one
// reciprocal of det), so that its t, u and v are those of Triangle::hit bit for bit, and so is
// its verdict `hit`. IEEE float rounds each operation alone, in a vector lane as in a scalar, as
// long as the compiler neither fuses a multiply and an add into one rounding (it may where the
// target has FMA, __FP_FAST_FMAF: the stress suite's FMA build, ARM64) nor reorders sums
// (-ffast-math). Then the two may round differently: a wider test that errs on the side of a hit
// (may_hit below) finds the lanes to leave to Triangle::hit. Where the pack is exact, that test is
// skipped: it would only hand Triangle::hit lanes that it rejects.
#if defined(__FP_FAST_FMAF) || defined(__FAST_MATH__)
constexpr bool PACK_IS_EXACT = false;
#else
constexpr bool PACK_IS_EXACT = true;
#endif

// What hit_pack finds for the four triangles of a pack (lane i: triangle i).
struct Pack_Hits {
	unsigned hit;        // a bit per triangle hit with t in ray.dist_bounds: Triangle::hit's verdict
	Float4 det, u, v, t; // Möller–Trumbore's determinant, barycentrics and ray parameter
};

template<typename Triangle_Pack>
[[gnu::always_inline]] inline Pack_Hits hit_pack(const Triangle_Pack& pack, const Ray& ray) {
	constexpr float EDGE_SLACK = 1e-5f; // Triangle::hit's
	Float4 e1[3], e2[3], s[3];
	for (int axis = 0; axis < 3; axis++) {
		e1[axis] = load4(pack.e1[axis]), e2[axis] = load4(pack.e2[axis]);
		s[axis] = ray.point[axis] - load4(pack.v0[axis]);
	}
	auto cross = [](const Float4* a, const Float4* b, Float4* out) {
		out[0] = a[1] * b[2] - a[2] * b[1], out[1] = a[2] * b[0] - a[0] * b[2], out[2] = a[0] * b[1] - a[1] * b[0];
	};
	auto dot_dir = [&](const Float4* a) { return ray.dir.x * a[0] + ray.dir.y * a[1] + ray.dir.z * a[2]; };
	// det = -d . n, u det = d . (e2 x s), v det = d . (s x e1), t det = s . n, n = e1 x e2.
	Float4 n[3], e2_s[3], s_e1[3];
	cross(e1, e2, n), cross(e2, s, e2_s), cross(s, e1, s_e1);
	Float4 det = -dot_dir(n);
	Float4 inv_det = 1.0f / det;
	Float4 u = dot_dir(e2_s) * inv_det, v = dot_dir(s_e1) * inv_det;
	Float4 t = (s[0] * n[0] + s[1] * n[1] + s[2] * n[2]) * inv_det;
	// Triangle::hit: det != 0, the edge slack, t in bounds (written positively: NaN fails).
	Int4 hit = (det != 0) & (u >= -EDGE_SLACK) & (v >= -EDGE_SLACK) & (u + v <= 1.0f + EDGE_SLACK) &
	           (t >= ray.dist_bounds.x) & (t <= ray.dist_bounds.y) & (t < INF_F);
	return Pack_Hits{lane_bits(hit), det, u, v, t};
}

// The wider test, for where the pack may round otherwise than Triangle::hit: a bit per triangle
// that may be hit (ten times the edge slack, t bounds widened by 1e-4 t), a superset of `hit`.
inline unsigned may_hit(const Pack_Hits& pack, const Ray& ray) {
	constexpr float WIDE_SLACK = 1e-4f;
	Float4 t = pack.t, u = pack.u, v = pack.v;
	Float4 t_margin = WIDE_SLACK * (t < 0 ? -t : t);
	Int4 maybe = (pack.det != 0) & (u >= -WIDE_SLACK) & (v >= -WIDE_SLACK) & (u + v <= 1 + WIDE_SLACK) &
	             (t >= ray.dist_bounds.x - t_margin) & (t <= ray.dist_bounds.y + t_margin);
	return lane_bits(maybe) | pack.hit;
}

// What the any-hit query returns when a pack finds a hit: occluded() reads only `hit`.
inline Trace occluder(float t) {
	Trace trace;
	trace.hit = true;
	trace.distance = t;
	return trace;
}

// Starts loading the cache lines of `size` bytes at `start` before they are used.
[[gnu::always_inline]] inline void prefetch(const void* start, size_t size) {
	const char* bytes = static_cast<const char*>(start);
	for (size_t offset = 0; offset < size; offset += 64) __builtin_prefetch(bytes + offset);
	__builtin_prefetch(bytes + size - 1); // the last line, when the bytes straddle one more
}

// What traversal fetches ahead for a leaf that a node's test finds (the leaves found are then
// fetched at once): its first pack, rarely in cache, and for the closest hit the pack's triangles,
// one of which the final Triangle::hit reads: fetched with the pack, it arrives while the pack
// is tested, not after.
template<bool ANY_HIT, typename Wide_Node>
[[gnu::always_inline]] inline void prefetch_leaf(const BVH<Triangle>& bvh, const Wide_Node& node, int slot) {
	prefetch(&bvh.triangle_packs[node.first[slot]], sizeof(bvh.triangle_packs[0]));
	if (!ANY_HIT) {
		uint32_t triangles = std::min<uint32_t>(node.count[slot], 4); // the first pack's
		prefetch(&bvh.primitives[node.start[slot]], triangles * sizeof(Triangle));
	}
}

// Front to back (handout §3.3) over wide_nodes: test a node's children four at a time, go down into
// the nearest child hit and keep the others on a stack, with the t at which the ray enters them.
// The closest-hit query (hit()) shrinks the ray to each hit it finds; the any-hit query
// (occluded()) returns at the first, and takes the children hit in slot order: any hit will do,
// so sorting them buys nothing (the answer, hit or not, is the same in any order).
// Triangles: a pack's test decides its four triangles (hit_pack) and the closest-hit query keeps
// the closest one's index; Triangle::hit then gives the record, on the whole ray, so the result is
// the lab's test bit for bit. If that misses (only where the pack rounded otherwise: fused
// multiply-add), the query starts over with `exact`: every candidate tested by Triangle::hit.
template<bool ANY_HIT, typename Primitive>
Trace traverse(const BVH<Primitive>& bvh, const Ray& ray, bool exact = false);
Trace record(const BVH<Triangle>& bvh, const Ray& ray, uint32_t best, bool exact);

template<bool ANY_HIT, typename Primitive>
Trace traverse(const BVH<Primitive>& bvh, const Ray& ray, bool exact) {
	struct Child { // a wide node (count 0) or a leaf's primitives
		uint32_t first, count;
		float t_enter;
	};
	// The children waiting, nearest on top: on the call stack (a thread_local vector's lookup cost
	// 4 % of a primary ray), moved to the heap if a deep tree fills it. 64 is three times what the
	// bench scenes' rays need.
	Child local_stack[64];
	std::vector<Child> heap_stack;
	Child* stack = local_stack;
	size_t capacity = std::size(local_stack), top = 0;

	Ray r = ray; // r.dist_bounds.y shrinks to the closest hit found so far
	Slab_Ray slab_ray(ray);
	Trace closest;
	constexpr uint32_t NONE = ~0u;
	uint32_t best = NONE; // triangles (closest hit): the closest triangle found, hit at r.dist_bounds.y
	if (bvh.wide_nodes.empty()) return closest;
	Child child{0, 0, ray.dist_bounds.x}; // the root

	while (true) {
		if (child.count > 0) {
			if constexpr (std::is_same_v<Primitive, Triangle>) {
				for (uint32_t p = child.first; p < child.first + (child.count + 3) / 4; p++) {
					const auto& pack = bvh.triangle_packs[p];
					Pack_Hits hits = hit_pack(pack, r);
					// Candidates the pack cannot decide (rounding with fused multiply-add), and in the
					// fallback below every candidate: the lab's test.
					unsigned undecided = PACK_IS_EXACT && !exact ? 0 : may_hit(hits, r);
					if (exact) hits.hit = 0;
					undecided &= ~hits.hit;
					for (unsigned lanes = undecided; lanes != 0; lanes &= lanes - 1) {
						uint32_t i = pack.index[__builtin_ctz(lanes)];
						Trace trace = bvh.primitives[i].hit(r);
						if (!trace.hit) continue;
						if (ANY_HIT) return trace;
						best = i, r.dist_bounds.y = trace.distance;
					}
					for (unsigned lanes = hits.hit; lanes != 0; lanes &= lanes - 1) {
						int lane = __builtin_ctz(lanes);
						if constexpr (ANY_HIT) {
							// The pack's verdict is Triangle::hit's: done, without loading the Triangle.
							// Otherwise the lab's test confirms it (one Triangle load per ray).
							if (PACK_IS_EXACT) return occluder(hits.t[lane]);
							Trace trace = bvh.primitives[pack.index[lane]].hit(r);
							if (trace.hit) return trace;
						} else if (hits.t[lane] <= r.dist_bounds.y) { // (an earlier lane may have come closer)
							best = pack.index[lane], r.dist_bounds.y = hits.t[lane];
						}
					}
				}
			} else {
				for (uint32_t i = child.first; i < child.first + child.count; i++) {
					closest = Trace::min(closest, bvh.primitives[i].hit(r));
					if (!closest.hit) continue;
					if (ANY_HIT) return closest;
					r.dist_bounds.y = closest.distance;
				}
			}
		} else {
			const auto& node = bvh.wide_nodes[child.first];
			constexpr int WIDTH = BVH<Primitive>::Wide_Node::WIDTH;
			float t_enter[WIDTH];
			unsigned mask = hit_children(node, slab_ray, r.dist_bounds, t_enter);
			if (mask != 0) {
				if (top + WIDTH > capacity) { // a deep tree: the stack moves to the heap, twice as large
					if (stack == local_stack) heap_stack.assign(local_stack, local_stack + top);
					heap_stack.resize(capacity *= 2);
					stack = heap_stack.data();
				}
				auto hit = [&](int slot) { return Child{node.first[slot], node.count[slot], t_enter[slot]}; };
				if constexpr (std::is_same_v<Primitive, Triangle>) { // the leaves found, fetched at once
					for (unsigned leaves = mask; leaves != 0; leaves &= leaves - 1) {
						int slot = __builtin_ctz(leaves);
						if (node.count[slot] > 0) prefetch_leaf<ANY_HIT>(bvh, node, slot);
					}
				}
				int near = __builtin_ctz(mask);
				mask &= mask - 1;
				if (mask == 0) { // one child hit (the common case): nothing to order
					child = hit(near);
					continue;
				}
				if constexpr (ANY_HIT) { // any hit ends the query: no order needed
					for (; mask != 0; mask &= mask - 1) stack[top++] = hit(__builtin_ctz(mask));
					child = hit(near);
					continue;
				}
				int far = __builtin_ctz(mask);
				mask &= mask - 1;
				if (mask == 0) { // two: the nearer first, the lower slot on a tie (as the sort below)
					if (t_enter[far] < t_enter[near]) std::swap(near, far);
					stack[top++] = hit(far);
					child = hit(near);
					continue;
				}
				// More: insertion sort, nearest first.
				Child hits[WIDTH] = {hit(near), hit(far)};
				if (hits[1].t_enter < hits[0].t_enter) std::swap(hits[0], hits[1]);
				int count = 2;
				for (; mask != 0; mask &= mask - 1) {
					Child c = hit(__builtin_ctz(mask));
					int at = count++;
					for (; at > 0 && hits[at - 1].t_enter > c.t_enter; at--) hits[at] = hits[at - 1];
					hits[at] = c;
				}
				for (int i = count - 1; i > 0; i--) stack[top++] = hits[i]; // the nearest is popped first
				child = hits[0];
				continue;
			}
		}
		// Pop the nearest pending child that still starts before the closest hit.
		while (top > 0 && stack[top - 1].t_enter > r.dist_bounds.y) top--;
		if (top == 0) break;
		child = stack[--top];
	}
	if constexpr (std::is_same_v<Primitive, Triangle>) {
		if (!ANY_HIT && best != NONE) return record(bvh, ray, best, exact);
	}
	return closest;
}

// The closest triangle's record (its normal, position): Triangle::hit on the whole ray, or if that
// misses, the `exact` query (above). Returned as one variable, the record is written once, where
// the caller wants it: a copy, read back before Triangle::hit's stores have landed, cost a primary
// ray several percent.
Trace record(const BVH<Triangle>& bvh, const Ray& ray, uint32_t best, bool exact) {
	Trace trace = bvh.primitives[best].hit(ray);
	if (!trace.hit && !exact) trace = traverse<false>(bvh, ray, true);
	return trace;
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

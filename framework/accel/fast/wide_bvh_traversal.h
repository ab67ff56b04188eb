#pragma once
// The fast accelerator's queries (wide_bvh_queries.h), written once for any vector width: `Lanes`
// is the test of a wide node's children (four_wide_tests.h, eight_wide_queries.cpp). Included only
// by the files that compile them, one per width, each with its own instruction set; everything here
// is in an unnamed namespace, so that each keeps its own copy (no program links code of one width
// where it asked for the other).
#include "four_wide_tests.h"
#include "instance.h"
#include "tri_mesh.h"
#include "wide_bvh_queries.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <utility>
#include <vector>

namespace {

using namespace four_wide;

constexpr uint32_t NONE = ~0u;

// Starts loading the cache lines of `size` bytes at `start` before they are used.
[[gnu::always_inline]] inline void prefetch(const void* start, size_t size) {
	const char* bytes = static_cast<const char*>(start);
	for (size_t offset = 0; offset < size; offset += 64) __builtin_prefetch(bytes + offset);
	__builtin_prefetch(bytes + size - 1); // the last line, when the bytes straddle one more
}

// The leaves of a BVH<Triangle>: a pack's test decides its four triangles (hit_pack), and the
// closest-hit query keeps the closest one's index and lane, hit at r.dist_bounds.y; of triangles hit
// at the same t, the lowest index, as Trace::min over BVH::primitives in order keeps it, so that the
// answer does not depend on the wide tree's shape or the order its packs are tested in. With `exact`
// (the fallback, see record()) or where the pack may round otherwise than Triangle::hit (fused
// multiply-add), the candidates go to Triangle::hit.
template<bool ANY_HIT> struct Triangle_Leaves {
	const BVH<Triangle>& bvh;
	const Wide_BVH& wide;
	bool exact;
	uint32_t best = NONE; // closest hit: the closest triangle found so far, hit at t
	uint32_t best_lane = 0; // and where the pack found it: pack * 4 + lane
	float t = INF_F;
	float u = 0, v = 0; // and its barycentrics (where the pack is exact, Triangle::hit's)

	// What a node's test fetches ahead for a leaf it finds (the leaves found are then fetched at
	// once). The closest hit: its packs, consecutive and rarely in cache, and the first pack's
	// normals, which the record most likely reads (fetched now, they arrive while the packs are
	// tested, not after; the other packs' too would cost more lines than they save). Any hit: the
	// leaf's first four lines, as much as a wide node's, since its first pack likely ends the query.
	[[gnu::always_inline]] void fetch(uint32_t first_pack, uint32_t count) const {
		uint32_t bytes = (count + 3) / 4 * uint32_t(sizeof(Triangle_Pack));
		const char* start = reinterpret_cast<const char*>(&wide.triangle_packs[first_pack]);
		if constexpr (ANY_HIT) {
			for (uint32_t offset = 0; offset < 4 * 64; offset += 64)
				__builtin_prefetch(start + std::min(offset, bytes - 1)); // none past the leaf's end
		} else {
			prefetch(start, bytes);
			prefetch(&wide.pack_normals[first_pack], sizeof(Pack_Normals));
		}
	}

	// Tests the leaf's triangles against r, lowering r.dist_bounds.y to each closer hit; returns
	// true where an any-hit query is answered.
	[[gnu::always_inline]] bool visit(uint32_t first_pack, uint32_t count, Ray& r) {
		for (uint32_t p = first_pack; p < first_pack + (count + 3) / 4; p++) {
			const Triangle_Pack& pack = wide.triangle_packs[p];
			Pack_Hits hits = hit_pack(pack, r);
			// Candidates the pack cannot decide, and in the fallback every candidate: the lab's test.
			unsigned undecided = PACK_IS_EXACT && !exact ? 0 : may_hit(hits, r);
			if (exact) hits.hit = 0;
			undecided &= ~hits.hit;
			for (unsigned lanes = undecided; lanes != 0; lanes &= lanes - 1) {
				int lane = __builtin_ctz(lanes);
				uint32_t i = pack.index[lane];
				Trace trace = bvh.primitives[i].hit(r);
				if (!trace.hit) continue;
				if (ANY_HIT) return true;
				if (trace.distance == t && i > best) continue; // a tie: the lower index wins
				best = i, best_lane = p * 4 + lane, t = r.dist_bounds.y = trace.distance;
			}
			for (unsigned lanes = hits.hit; lanes != 0; lanes &= lanes - 1) {
				int lane = __builtin_ctz(lanes);
				if constexpr (ANY_HIT) {
					// The pack's verdict is Triangle::hit's: done, without loading the Triangle.
					// Otherwise the lab's test confirms it.
					if (PACK_IS_EXACT || bvh.primitives[pack.index[lane]].hit(r).hit) return true;
				} else if (hits.t[lane] < t || (hits.t[lane] == t && pack.index[lane] < best)) {
					// Closer (than an earlier lane too), or a tie that the lower index wins.
					best = pack.index[lane], best_lane = p * 4 + lane, t = r.dist_bounds.y = hits.t[lane];
					u = hits.u[lane], v = hits.v[lane];
				}
			}
		}
		return false;
	}
};

// The leaves of a BVH<Instance>: Instance::hit on each object, the closest record kept.
template<bool ANY_HIT> struct Instance_Leaves {
	const BVH<Instance>& bvh;
	Trace closest;

	void fetch(uint32_t, uint32_t) const {
	}

	bool visit(uint32_t first, uint32_t count, Ray& r) {
		for (uint32_t i = first; i < first + count; i++) {
			closest = Trace::min(closest, bvh.primitives[i].hit(r));
			if (!closest.hit) continue;
			if (ANY_HIT) return true;
			r.dist_bounds.y = closest.distance;
		}
		return false;
	}
};

// The children of wide nodes that a query has found and not yet visited: on the call stack rather
// than behind a thread-local lookup, moved to the heap if a deep tree fills it (64 is three times
// what the benchmark scenes' rays need; the stress suite has a deeper tree).
template<typename Child> struct Waiting {
	Child local[64];
	std::vector<Child> heap;
	Child* items = local;
	size_t capacity = std::size(local), size = 0;

	Waiting() = default;
	Waiting(const Waiting&) = delete; // `items` may point into `local`
	Waiting& operator=(const Waiting&) = delete;

	// Room for one more node's children.
	void make_room() {
		if (size + Wide_Node::WIDTH <= capacity) return;
		if (items == local) heap.assign(local, local + size);
		heap.resize(capacity *= 2);
		items = heap.data();
	}
	void push(Child child) {
		items[size++] = child;
	}
	Child pop() {
		return items[--size];
	}
};

// Starts loading a child that a node's test found: a wide node whole, a leaf as `leaves` fetches it.
template<typename Leaves>
[[gnu::always_inline]] inline void fetch_child(const Wide_BVH& wide, const Wide_Node& node, int slot,
                                               const Leaves& leaves) {
	if (node.count[slot] > 0) leaves.fetch(node.first[slot], node.count[slot]);
	else prefetch(&wide.nodes[node.first[slot]], sizeof(Wide_Node));
}

// The closest hit, front to back (handouts/task3_bvh.md §3.3) over the wide nodes: test a node's
// children (Lanes::hit_children), fetch those hit, go down into the nearest and keep the others
// waiting, with the t at which the ray enters them; at a leaf, leaves.visit(), which shrinks the ray
// to each hit it finds, so that the children waiting beyond it are dropped.
template<typename Lanes, typename Leaves>
void traverse_closest(const Wide_BVH& wide, const Ray& ray, Leaves& leaves) {
	struct Child { // a wide node (count 0) or a leaf's primitives
		uint32_t first, count;
		float t_enter;
	};
	Waiting<Child> waiting;
	Ray r = ray; // r.dist_bounds.y shrinks to the closest hit found so far
	Slab_Ray slab_ray(ray);
	if (wide.nodes.empty()) return;
	Child child{0, 0, ray.dist_bounds.x}; // the root

	while (true) {
		if (child.count > 0) {
			leaves.visit(child.first, child.count, r);
		} else {
			const Wide_Node& node = wide.nodes[child.first];
			constexpr int WIDTH = Wide_Node::WIDTH;
			float t_enter[WIDTH], t_exit[WIDTH];
			unsigned mask = Lanes::hit_children(node, slab_ray, r.dist_bounds, t_enter, t_exit);
			if (mask != 0) {
				waiting.make_room();
				auto hit = [&](int slot) { return Child{node.first[slot], node.count[slot], t_enter[slot]}; };
				// The children found, fetched at once (unless the tree stays in the cache anyway).
				for (unsigned found = wide.fits_in_cache ? 0 : mask; found != 0; found &= found - 1)
					fetch_child(wide, node, __builtin_ctz(found), leaves);
				int near = __builtin_ctz(mask);
				mask &= mask - 1;
				if (mask == 0) { // one child hit (the common case): nothing to order
					child = hit(near);
					continue;
				}
				int far = __builtin_ctz(mask);
				mask &= mask - 1;
				if (mask == 0) { // two: the nearer first, the lower slot on a tie (as the sort below)
					if (t_enter[far] < t_enter[near]) std::swap(near, far);
					waiting.push(hit(far));
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
				for (int i = count - 1; i > 0; i--) waiting.push(hits[i]); // the nearest is popped first
				child = hits[0];
				continue;
			}
		}
		// Pop the nearest waiting child that still starts before the closest hit.
		while (waiting.size > 0 && waiting.items[waiting.size - 1].t_enter > r.dist_bounds.y) waiting.size--;
		if (waiting.size == 0) return;
		child = waiting.pop();
	}
}

// Any hit (an occlusion query): the first hit found answers it, whatever the order, so the order
// only decides how soon. Of the children a node's test finds, the query goes first into the one
// whose box holds the longest piece of the ray (the likeliest to hold a hit: a surface spread
// through a box is met in proportion to the length crossed), not counting the boxes that hold the
// ray's start (their piece counts 0): rays start on a surface, which they leave there. The others
// wait unsorted: sorting costs more than it saves. Each child found is fetched at once: a wide node
// whole, a leaf's first lines (leaves.fetch()). Returns whether a hit was found.
template<typename Lanes, typename Leaves>
bool traverse_any(const Wide_BVH& wide, const Ray& ray, Leaves& leaves) {
	struct Child { // a wide node (count 0) or a leaf's primitives
		uint32_t first, count;
	};
	Waiting<Child> waiting;
	Ray r = ray; // for leaves.visit(), which shrinks only a closest hit's ray
	Slab_Ray slab_ray(ray);
	if (wide.nodes.empty()) return false;
	Child child{0, 0}; // the root

	while (true) {
		if (child.count > 0) {
			if (leaves.visit(child.first, child.count, r)) return true;
		} else {
			const Wide_Node& node = wide.nodes[child.first];
			constexpr int WIDTH = Wide_Node::WIDTH;
			float t_enter[WIDTH], t_exit[WIDTH];
			unsigned mask = Lanes::hit_children(node, slab_ray, ray.dist_bounds, t_enter, t_exit);
			if (mask != 0) {
				waiting.make_room();
				// Every child found waits; the one with the longest piece (the first of equals) is then
				// taken back out, to be visited next.
				int next_slot = __builtin_ctz(mask);
				size_t next_at = waiting.size;
				float longest = -1.0f;
				for (unsigned found = mask; found != 0; found &= found - 1) {
					int slot = __builtin_ctz(found);
					if (!wide.fits_in_cache) fetch_child(wide, node, slot, leaves);
					float piece = t_enter[slot] > ray.dist_bounds.x ? t_exit[slot] - t_enter[slot] : 0.0f;
					bool longer = piece > longest;
					longest = longer ? piece : longest;
					next_slot = longer ? slot : next_slot;
					next_at = longer ? waiting.size : next_at;
					waiting.push(Child{node.first[slot], node.count[slot]});
				}
				child = Child{node.first[next_slot], node.count[next_slot]};
				waiting.items[next_at] = waiting.pop(); // (the last in its place)
				continue;
			}
		}
		if (waiting.size == 0) return false;
		child = waiting.pop();
	}
}

// The closest triangle hit with t in ray.dist_bounds, that t and its barycentrics (NONE and INF_F
// for a miss), and where the packs hold it (pack * 4 + lane).
struct Closest_Triangle {
	uint32_t primitive;
	float t, u, v;
	uint32_t lane;
};

template<typename Lanes>
Closest_Triangle closest_triangle(const BVH<Triangle>& bvh, const Wide_BVH& wide, const Ray& ray, bool exact) {
	Triangle_Leaves<false> leaves{bvh, wide, exact};
	traverse_closest<Lanes>(wide, ray, leaves);
	return Closest_Triangle{leaves.best, leaves.t, leaves.u, leaves.v, leaves.best_lane};
}

// The closest triangle's record (hit point, normal), bit for bit Triangle::hit's on the whole ray.
// Where the pack is exact, its t, u and v are Triangle::hit's, and the record is made from them with
// Triangle::hit's arithmetic (reference/task2_shapes.cpp: the vertex normals, here the pack's copy,
// weighted by 1 - u - v, u and v, normalized; the point ray.at(t)), without testing or reading the
// triangle again. Otherwise Triangle::hit makes it; if that misses (the pack rounded otherwise), the
// query starts over with `exact`: every candidate to Triangle::hit, and `best` becomes the triangle
// it finds (NONE and a miss, Trace{}, if it finds none). The record is written into `trace`, the one
// variable each query returns (so that it is made where the caller wants it: a record built in a
// temporary and copied costs more than making it, the copy's loads waiting on the temporary's
// stores).
template<typename Lanes>
void record(const BVH<Triangle>& bvh, const Wide_BVH& wide, const Ray& ray, Closest_Triangle& best, Trace& trace) {
	if constexpr (PACK_IS_EXACT) {
		float u = best.u, v = best.v;
		const Vec3* normal = wide.pack_normals[best.lane / 4].normal[best.lane % 4]; // at v0, v1, v2
		trace.origin = ray.point;
		trace.hit = true;
		trace.distance = best.t;
		trace.position = ray.at(best.t);
		trace.normal = glm::normalize((1.0f - u - v) * normal[0] + u * normal[1] + v * normal[2]);
		return;
	}
	trace = bvh.primitives[best.primitive].hit(ray);
	if (!trace.hit) {
		best = closest_triangle<Lanes>(bvh, wide, ray, true);
		trace = best.primitive != NONE ? bvh.primitives[best.primitive].hit(ray) : Trace{};
	}
}

// A scene's closest hit through its flat meshes (wide_bvh.h): the closest triangle of the flat
// meshes, then the other objects up to it; a triangle's record is made as its object's hit() makes
// it (Triangle::hit's, record(), then Instance::world_record, both in place).
template<typename Lanes> Trace flat_hit(const BVH<Instance>& objects, const Flat_Meshes& flat, const Ray& ray) {
	Closest_Triangle nearest = closest_triangle<Lanes>(flat.triangles, flat.wide, ray, false);
	Trace trace;
	if (!flat.others.nodes.empty()) {
		Instance_Leaves<false> others{objects, Trace{}};
		Ray rest = ray;
		rest.dist_bounds.y = std::min(rest.dist_bounds.y, nearest.t);
		traverse_closest<Lanes>(flat.others, rest, others);
		if (others.closest.hit) {
			trace = others.closest;
			return trace;
		}
	}
	if (nearest.primitive == NONE) return trace;
	record<Lanes>(flat.triangles, flat.wide, ray, nearest, trace);
	if (trace.hit) objects.primitives[flat.owner[nearest.primitive]].world_record(ray, trace);
	return trace;
}

template<typename Lanes> bool flat_occluded(const BVH<Instance>& objects, const Flat_Meshes& flat, const Ray& ray) {
	Triangle_Leaves<true> triangles{flat.triangles, flat.wide, false};
	if (traverse_any<Lanes>(flat.wide, ray, triangles)) return true;
	Instance_Leaves<true> others{objects, Trace{}};
	return traverse_any<Lanes>(flat.others, ray, others);
}


// The four queries of wide_bvh_queries.h, with the node test `Lanes`.
template<typename Lanes> struct Queries {
	static Trace hit_triangles(const BVH<Triangle>& bvh, const Wide_BVH& wide, const Ray& ray) {
		Closest_Triangle best = closest_triangle<Lanes>(bvh, wide, ray, false);
		Trace trace;
		if (best.primitive != NONE) record<Lanes>(bvh, wide, ray, best, trace);
		return trace;
	}
	static bool triangles_occluded(const BVH<Triangle>& bvh, const Wide_BVH& wide, const Ray& ray) {
		Triangle_Leaves<true> leaves{bvh, wide, false};
		return traverse_any<Lanes>(wide, ray, leaves);
	}
	static Trace hit_objects(const BVH<Instance>& bvh, const Wide_BVH& wide, const Ray& ray) {
		if (wide.flat) return flat_hit<Lanes>(bvh, *wide.flat, ray);
		Instance_Leaves<false> leaves{bvh, Trace{}};
		traverse_closest<Lanes>(wide, ray, leaves);
		return leaves.closest;
	}
	static bool objects_occluded(const BVH<Instance>& bvh, const Wide_BVH& wide, const Ray& ray) {
		if (wide.flat) return flat_occluded<Lanes>(bvh, *wide.flat, ray);
		Instance_Leaves<true> leaves{bvh, Trace{}};
		return traverse_any<Lanes>(wide, ray, leaves);
	}
	static constexpr Wide_Queries table(int lanes) {
		return Wide_Queries{lanes, hit_triangles, triangles_occluded, hit_objects, objects_occluded};
	}
};

} // namespace

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
	// once): its packs, consecutive and rarely in cache, and for the closest hit the first pack's
	// normals, which the record most likely reads (fetched now, they arrive while the packs are
	// tested, not after; the other packs' too would cost more lines than they save).
	[[gnu::always_inline]] void prefetch_leaf(const Wide_Node& node, int slot) const {
		uint32_t packs = (node.count[slot] + 3) / 4;
		prefetch(&wide.triangle_packs[node.first[slot]], packs * sizeof(Triangle_Pack));
		if (!ANY_HIT) prefetch(&wide.pack_normals[node.first[slot]], sizeof(Pack_Normals));
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

	void prefetch_leaf(const Wide_Node&, int) const {
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

// Front to back (handouts/task3_bvh.md §3.3) over the wide nodes: test a node's children
// (Lanes::hit_children), fetch those hit, go down into the nearest and keep the others on a stack,
// with the t at which the ray enters them; at a leaf, leaves.visit(). The closest-hit query shrinks
// the ray to each hit it finds; the any-hit query returns at the first, and takes first the child
// hit whose box holds the longest piece of the ray (the likeliest to hold a hit: a surface spread
// through a box is met in proportion to the length crossed), then the others in slot order, the
// largest box first (widen()): any hit will do (the answer is the same in any order), and sorting
// them all costs more than it saves. Returns whether an any-hit query found a hit.
template<bool ANY_HIT, typename Lanes, typename Leaves>
bool traverse(const Wide_BVH& wide, const Ray& ray, Leaves& leaves) {
	struct Child { // a wide node (count 0) or a leaf's primitives
		uint32_t first, count;
		float t_enter;
	};
	// The children waiting, nearest on top: on the call stack rather than behind a thread-local
	// lookup, moved to the heap if a deep tree fills it (64 is three times what the benchmark
	// scenes' rays need; the stress suite has a deeper tree).
	Child local_stack[64];
	std::vector<Child> heap_stack;
	Child* stack = local_stack;
	size_t capacity = std::size(local_stack), top = 0;

	Ray r = ray; // r.dist_bounds.y shrinks to the closest hit found so far
	Slab_Ray slab_ray(ray);
	if (wide.nodes.empty()) return false;
	Child child{0, 0, ray.dist_bounds.x}; // the root

	while (true) {
		if (child.count > 0) {
			if (leaves.visit(child.first, child.count, r)) return true;
		} else {
			const Wide_Node& node = wide.nodes[child.first];
			constexpr int WIDTH = Wide_Node::WIDTH;
			float t_enter[WIDTH], t_exit[WIDTH];
			unsigned mask = Lanes::hit_children(node, slab_ray, r.dist_bounds, t_enter, t_exit);
			if (mask != 0) {
				if (top + WIDTH > capacity) { // a deep tree: the stack moves to the heap, twice as large
					if (stack == local_stack) heap_stack.assign(local_stack, local_stack + top);
					heap_stack.resize(capacity *= 2);
					stack = heap_stack.data();
				}
				auto hit = [&](int slot) { return Child{node.first[slot], node.count[slot], t_enter[slot]}; };
				// The children found, fetched at once (unless the tree stays in the cache anyway).
				for (unsigned found = wide.fits_in_cache ? 0 : mask; found != 0; found &= found - 1) {
					int slot = __builtin_ctz(found);
					if (node.count[slot] > 0) leaves.prefetch_leaf(node, slot);
					else prefetch(&wide.nodes[node.first[slot]], sizeof(Wide_Node));
				}
				int near = __builtin_ctz(mask);
				mask &= mask - 1;
				if (mask == 0) { // one child hit (the common case): nothing to order
					child = hit(near);
					continue;
				}
				if constexpr (ANY_HIT) {
					// Any hit ends the query: the longest crossing first, then the others in slot order.
					int longest = near;
					for (unsigned others = mask; others != 0; others &= others - 1) {
						int slot = __builtin_ctz(others);
						if (t_exit[slot] - t_enter[slot] > t_exit[longest] - t_enter[longest]) longest = slot;
					}
					unsigned rest = (mask | 1u << near) & ~(1u << longest);
					while (rest != 0) { // pushed from the highest slot down, so the lowest is popped next
						int slot = 31 - __builtin_clz(rest);
						stack[top++] = hit(slot);
						rest &= ~(1u << slot);
					}
					child = hit(longest);
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
	return false;
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
	traverse<false, Lanes>(wide, ray, leaves);
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
		traverse<false, Lanes>(flat.others, rest, others);
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
	if (traverse<true, Lanes>(flat.wide, ray, triangles)) return true;
	Instance_Leaves<true> others{objects, Trace{}};
	return traverse<true, Lanes>(flat.others, ray, others);
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
		return traverse<true, Lanes>(wide, ray, leaves);
	}
	static Trace hit_objects(const BVH<Instance>& bvh, const Wide_BVH& wide, const Ray& ray) {
		if (wide.flat) return flat_hit<Lanes>(bvh, *wide.flat, ray);
		Instance_Leaves<false> leaves{bvh, Trace{}};
		traverse<false, Lanes>(wide, ray, leaves);
		return leaves.closest;
	}
	static bool objects_occluded(const BVH<Instance>& bvh, const Wide_BVH& wide, const Ray& ray) {
		if (wide.flat) return flat_occluded<Lanes>(bvh, *wide.flat, ray);
		Instance_Leaves<true> leaves{bvh, Trace{}};
		return traverse<true, Lanes>(wide, ray, leaves);
	}
	static constexpr Wide_Queries table(int lanes) {
		return Wide_Queries{lanes, hit_triangles, triangles_occluded, hit_objects, objects_occluded};
	}
};

} // namespace

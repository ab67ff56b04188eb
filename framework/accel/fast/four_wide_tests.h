#pragma once
// The fast accelerator's ray tests, four boxes or four triangles at once (wide_bvh.h layouts):
// the lab's slab test (handouts/task3_bvh.md §3.1) and Möller–Trumbore (handouts/task2_shapes.md
// §2.1), lane by lane, in GCC's and Clang's vector extension (arithmetic and comparisons work lane
// by lane; a comparison gives 0 or -1 per lane), which compiles to one SSE or NEON instruction per
// operation.
#include "wide_bvh.h"

#include <cstring>

namespace four_wide {

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

inline Float4 load4(const float* values) {
	Float4 v;
	std::memcpy(&v, values, sizeof v);
	return v;
}

// A ray prepared for many slab tests, computed once: the reciprocal direction, and on each axis the
// bounds of a Wide_Node that the ray meets first (`near`: min_x where it points to +x, max_x where
// to -x) and last (`far`), so that a node's test loads them without asking the direction's sign.
struct Slab_Ray {
	using Bounds = float (Wide_Node::*)[Wide_Node::WIDTH]; // min_x, ..., max_z
	explicit Slab_Ray(const Ray& ray) : point(ray.point) {
		constexpr Bounds lower[3] = {&Wide_Node::min_x, &Wide_Node::min_y, &Wide_Node::min_z};
		constexpr Bounds upper[3] = {&Wide_Node::max_x, &Wide_Node::max_y, &Wide_Node::max_z};
		Float4 inverse = 1.0f / Float4{ray.dir.x, ray.dir.y, ray.dir.z, 1.0f}; // three divisions in one
		for (int axis = 0; axis < 3; axis++) {
			inv_dir[axis] = inverse[axis];
			bool negative = inverse[axis] < 0.0f;
			near[axis] = negative ? upper[axis] : lower[axis];
			far[axis] = negative ? lower[axis] : upper[axis];
		}
	}
	Vec3 point;
	Vec3 inv_dir; // +-inf where a direction component is +-0
	Bounds near[3], far[3];
};

// The node test of the four-wide queries (wide_bvh_traversal.h): the slab test of a wide node's
// children, four at once.
struct Four_Lanes {
	// Returns a bit per child hit within `bounds` (never an unused slot: its box is empty, but a ray
	// with a NaN direction overlaps every box), and where the ray enters and leaves each child's box.
	[[gnu::always_inline]] static unsigned hit_children(const Wide_Node& node, const Slab_Ray& ray, Vec2 bounds,
	                                                    float (&t_enter)[Wide_Node::WIDTH],
	                                                    float (&t_exit)[Wide_Node::WIDTH]) {
		unsigned mask = 0;
		for (int group = 0; group < Wide_Node::WIDTH; group += 4) { // four children at a time
			Float4 enter = Float4{} + bounds.x, exit = Float4{} + bounds.y;
			for (int axis = 0; axis < 3; axis++) {
				Float4 t_near = (load4(node.*ray.near[axis] + group) - ray.point[axis]) * ray.inv_dir[axis];
				Float4 t_far = (load4(node.*ray.far[axis] + group) - ray.point[axis]) * ray.inv_dir[axis];
				// A NaN (0 * inf, a ray inside a slab's plane) fails the comparison and leaves the
				// interval unchanged.
				enter = t_near > enter ? t_near : enter;
				exit = t_far < exit ? t_far : exit;
			}
			std::memcpy(t_enter + group, &enter, sizeof enter);
			std::memcpy(t_exit + group, &exit, sizeof exit);
			Int4 first;
			std::memcpy(&first, node.first + group, sizeof first);
			Int4 hit = (enter <= exit) & (first != Int4{} + int32_t(Wide_Node::UNUSED_SLOT));
			mask |= lane_bits(hit) << group;
		}
		return mask;
	}
};

// Möller–Trumbore on the four triangles of a pack at once, with Triangle::hit's arithmetic
// (reference/task2_shapes.cpp: the same products and sums in the same order, one reciprocal of
// det), so that its t, u and v are those of Triangle::hit bit for bit, and so is its verdict `hit`.
// IEEE float rounds each operation alone, in a vector lane as in a scalar, as long as the compiler
// neither fuses a multiply and an add into one rounding (it may where the target has FMA,
// __FP_FAST_FMAF: the stress suite's FMA build, ARM64) nor reorders sums (-ffast-math). Then the
// two may round differently: a wider test that errs on the side of a hit (may_hit below) finds the
// lanes to leave to Triangle::hit. Where the pack is exact, that test is skipped: it would only
// hand Triangle::hit lanes that it rejects.
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

} // namespace four_wide

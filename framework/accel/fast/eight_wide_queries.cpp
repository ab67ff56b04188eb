// The fast accelerator's queries with eight lanes (wide_bvh_queries.h): a wide node's eight children
// tested at once, with AVX, on x86-64 CPUs that have AVX2; a program built for any x86-64 CPU takes
// them where the CPU has them. Only the functions below the instruction-set switch use AVX: every
// header is included before it, so that the library code they hold stays compiled for any CPU (the
// queries inline it). No fused multiply-add is switched on: the packs' arithmetic stays exact.
#include "four_wide_tests.h"
#include "instance.h"
#include "tri_mesh.h"
#include "wide_bvh_queries.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>
#include <utility>
#include <vector>

#if defined(__x86_64__)

#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2")
#endif

namespace {

using Float8 = float __attribute__((vector_size(32)));
using Int8 = int32_t __attribute__((vector_size(32)));

// Eight floats at `values`, 32-byte aligned (a Wide_Node's arrays are).
Float8 load8(const float* values) {
	using Aligned_Floats = float __attribute__((vector_size(32), may_alias));
	return *reinterpret_cast<const Aligned_Floats*>(values);
}

// The node test: the lab's slab test (handouts/task3_bvh.md §3.1) of all eight children at once,
// otherwise as Four_Lanes (four_wide_tests.h), which it answers bit for bit.
struct Eight_Lanes {
	[[gnu::always_inline]] static unsigned hit_children(const Wide_Node& node, const four_wide::Slab_Ray& ray,
	                                                    Vec2 bounds, float (&t_enter)[Wide_Node::WIDTH],
	                                                    float (&t_exit)[Wide_Node::WIDTH]) {
		static_assert(Wide_Node::WIDTH == 8);
		Float8 enter = Float8{} + bounds.x, exit = Float8{} + bounds.y;
		for (int axis = 0; axis < 3; axis++) {
			Float8 t_near = (load8(node.*ray.near[axis]) - ray.point[axis]) * ray.inv_dir[axis];
			Float8 t_far = (load8(node.*ray.far[axis]) - ray.point[axis]) * ray.inv_dir[axis];
			enter = t_near > enter ? t_near : enter; // (a NaN leaves the interval unchanged)
			exit = t_far < exit ? t_far : exit;
		}
		std::memcpy(t_enter, &enter, sizeof enter);
		std::memcpy(t_exit, &exit, sizeof exit);
		Int8 first;
		std::memcpy(&first, node.first, sizeof first);
		Int8 hit = (enter <= exit) & (first != Int8{} + int32_t(Wide_Node::UNUSED_SLOT));
		return unsigned(__builtin_ia32_movmskps256(Float8(hit))); // the eight sign bits
	}
};

} // namespace

#include "wide_bvh_traversal.h"

namespace {
const Wide_Queries eight_lanes = Queries<Eight_Lanes>::table(8);
}

#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif

const Wide_Queries* eight_wide_queries() {
	return __builtin_cpu_supports("avx2") ? &eight_lanes : nullptr;
}

#else

const Wide_Queries* eight_wide_queries() {
	return nullptr;
}

#endif

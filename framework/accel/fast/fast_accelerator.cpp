// The fast accelerator (api/accelerator.h): the queries of a finished BVH traverse its Wide_BVH
// (wide_bvh.h), with the widest vectors the CPU has (wide_bvh_queries.h). Linked only where tasks 2
// and 3 are both the reference (cmake/lab.cmake).
#include "accelerator.h"
#include "wide_bvh.h"
#include "wide_bvh_queries.h"

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <type_traits>

// Chosen once per process: the widest the CPU runs, unless LAB_VECTOR_WIDTH asks for a width.
const Wide_Queries& chosen_queries() {
	static const Wide_Queries& chosen = []() -> const Wide_Queries& {
		const Wide_Queries* eight = eight_wide_queries();
		const char* asked = std::getenv("LAB_VECTOR_WIDTH");
		std::string width = asked ? asked : "";
		if (width.empty()) return eight ? *eight : four_wide_queries;
		if (width == "4") return four_wide_queries;
		if (width == "8" && eight) return *eight;
		if (width == "8")
			throw std::runtime_error("LAB_VECTOR_WIDTH=8: this CPU has no AVX2 (x86-64), so the BVH's queries take "
			                         "four lanes; leave LAB_VECTOR_WIDTH unset or set it to 4");
		throw std::runtime_error("LAB_VECTOR_WIDTH=" + width +
		                         ": expected 4 or 8 (the lanes of the BVH's node test), or unset for the widest the CPU has");
	}();
	return chosen;
}

template<typename Primitive> Accelerator<Primitive>::Accelerator(const BVH<Primitive>& bvh) {
	Wide_BVH folded;
	if constexpr (std::is_same_v<Primitive, Instance>) folded.flat = flatten(bvh);
	if (!folded.flat) folded = widen(bvh);
	folded.queries = &chosen_queries();
	wide = std::make_shared<const Wide_BVH>(std::move(folded));
}

template<typename Primitive> Trace Accelerator<Primitive>::hit(const BVH<Primitive>& bvh, const Ray& ray) const {
	if (!wide) return bvh.hit(ray);
	if constexpr (std::is_same_v<Primitive, Triangle>) return wide->queries->hit_triangles(bvh, *wide, ray);
	else return wide->queries->hit_objects(bvh, *wide, ray);
}

template<typename Primitive> bool Accelerator<Primitive>::occluded(const BVH<Primitive>& bvh, const Ray& ray) const {
	if (!wide) return bvh.hit(ray).hit;
	if constexpr (std::is_same_v<Primitive, Triangle>) return wide->queries->triangles_occluded(bvh, *wide, ray);
	else return wide->queries->objects_occluded(bvh, *wide, ray);
}

template<typename Primitive> size_t Accelerator<Primitive>::bytes() const {
	if (!wide) return 0;
	size_t bytes = wide->bytes();
	if (wide->flat) {
		const Flat_Meshes& flat = *wide->flat;
		bytes += flat.wide.bytes() + flat.others.bytes() + flat.owner.capacity() * sizeof(uint32_t) +
		         flat.triangles.nodes.capacity() * sizeof(flat.triangles.nodes[0]) +
		         flat.triangles.primitives.capacity() * sizeof(Triangle);
	}
	return bytes;
}

template class Accelerator<Triangle>;
template class Accelerator<Instance>;

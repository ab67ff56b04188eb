// The plain accelerator (accelerator.h): no data of its own, every query is task 3's BVH::hit, which
// calls task 2's Triangle::hit on every candidate. Linked wherever task 2 or task 3 is not the
// reference (cmake/lab.cmake), so that a student's code runs end to end.
#include "accelerator.h"
#include "instance.h"
#include "tri_mesh.h"

template<typename Primitive> Accelerator<Primitive>::Accelerator(const BVH<Primitive>&) {
}

template<typename Primitive> Trace Accelerator<Primitive>::hit(const BVH<Primitive>& bvh, const Ray& ray) const {
	return bvh.hit(ray);
}

template<typename Primitive> bool Accelerator<Primitive>::occluded(const BVH<Primitive>& bvh, const Ray& ray) const {
	return bvh.hit(ray).hit;
}

template<typename Primitive> size_t Accelerator<Primitive>::bytes() const {
	return 0;
}

template class Accelerator<Triangle>;
template class Accelerator<Instance>;

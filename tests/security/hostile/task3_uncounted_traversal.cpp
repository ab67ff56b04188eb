// Hostile: a traversal of scene objects that tests them behind the counter's back. Everything but
// BVH<Instance>::hit is the reference's (the placeholder below: its file up to the explicit
// instantiations). BVH<Instance>::hit scans every object, intersecting its shape itself (as
// Instance::hit would) and calling Instance::hit only on the closest one, so that a count kept where
// the code runs sees one object tested per ray that hits: a linear scan passed off as better than
// any BVH.
@REFERENCE_BVH@

#include <variant>

template<> Trace BVH<Instance>::hit(const Ray& ray) const {
	const Instance* closest_object = nullptr;
	float closest = ray.dist_bounds.y;
	for (const Instance& object : primitives) {
		Ray local = object.identity ? ray
		                            : Ray(transform_point(object.to_local, ray.point),
		                                  transform_direction(object.to_local, ray.dir), ray.dist_bounds, ray.depth);
		local.dist_bounds.y = closest;
		Trace trace = std::visit([&](const auto& shape) { return shape.hit(local); }, object.shape);
		if (trace.hit) closest = trace.distance, closest_object = &object;
	}
	return closest_object ? closest_object->hit(ray) : Trace{};
}

template class BVH<Triangle>;
template class BVH<Instance>;

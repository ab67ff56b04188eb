#pragma once
// A scene object: a shape in its own local space, placed in the world by a transform. A transform
// with a negative determinant (a mirror, a scale of -1) also turns the shape inside out: its normals
// point inwards, so e.g. a sphere scaled by -1 emits towards its centre.
#include "shapes.h"
#include "tri_mesh.h"

#include <variant>

struct Instance {
	Instance(std::variant<Sphere, Tri_Mesh> shape, Mat4 to_world, uint32_t material, uint32_t index);

	// Intersects the shape in local space (ray parameters t are unchanged by affine transforms)
	// and returns the hit in world space, with `object` and `material` filled in.
	Trace hit(const Ray& ray) const;
	// What hit() makes of the shape's own record of `ray`, in place: the hit in world space, with
	// `object` and `material` filled in.
	void world_record(const Ray& ray, Trace& record) const {
		if (!record.hit) return;
		record.origin = ray.point;
		record.position = ray.at(record.distance);
		record.normal = glm::normalize(identity ? record.normal : normal_to_world * record.normal);
		record.object = index;
		record.material = material;
	}
	BBox bbox() const {
		return world_bbox;
	}

	std::variant<Sphere, Tri_Mesh> shape;
	Mat4 to_world{1.0f}, to_local{1.0f};
	Mat3 normal_to_world{1.0f}; // inverse transpose of the linear part
	uint32_t material = 0;
	uint32_t index = 0; // position in the scene description
	bool identity = false; // to_world is the identity: hit() skips the transforms
	BBox world_bbox;
};

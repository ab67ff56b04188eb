#include "bench_geometry.h"
#include "obj_loader.h"
#include "scene_loader.h"

#include <glm/gtc/matrix_inverse.hpp>

namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
	return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

Tri_Mesh_Vert to_world(const Instance& instance, const Tri_Mesh_Vert& v) {
	return Tri_Mesh_Vert{transform_point(instance.to_world, v.position),
	                     glm::normalize(instance.normal_to_world * v.normal)};
}

// A camera looking at the box from the front, a little from above, with the box filling the view.
Camera framing_camera(const BBox& box) {
	Vec3 center = box.center();
	float radius = 0.5f * glm::length(box.max - box.min);
	float distance = radius / std::tan(glm::radians(15.0f)); // 30° vertical field of view
	return Camera::look_at(center + distance * glm::normalize(Vec3{0.3f, 0.4f, 1.0f}), center, Vec3{0, 1, 0},
	                       30.0f, 4.0f / 3.0f);
}

} // namespace

Bench_Geometry load_bench_geometry(const std::string& path) {
	Bench_Geometry geometry;
	if (ends_with(path, ".obj")) {
		geometry.triangles = load_obj(path);
	} else {
		Scene scene = load_scene(path);
		geometry.camera = scene.camera;
		for (const Instance& instance : scene.bvh.primitives) {
			auto mesh = std::get_if<Tri_Mesh>(&instance.shape);
			if (!mesh) continue;
			for (const Triangle& t : mesh->bvh.primitives)
				geometry.triangles.push_back(
					Triangle{to_world(instance, t.v0), to_world(instance, t.v1), to_world(instance, t.v2)});
		}
	}
	for (const Triangle& t : geometry.triangles) geometry.bounds.enclose(t.bbox());
	if (ends_with(path, ".obj")) geometry.camera = framing_camera(geometry.bounds);
	return geometry;
}

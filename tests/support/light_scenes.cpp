#include "light_scenes.h"

namespace {
Triangle flat_triangle(Vec3 a, Vec3 b, Vec3 c) {
	Vec3 n = glm::normalize(glm::cross(b - a, c - a));
	return Triangle{{a, n}, {b, n}, {c, n}};
}
} // namespace

Tri_Mesh parallelogram(Vec3 corner, Vec3 u, Vec3 v) {
	Vec3 p0 = corner, p1 = corner + u, p2 = corner + u + v, p3 = corner + v;
	return Tri_Mesh({flat_triangle(p0, p1, p2), flat_triangle(p0, p2, p3)});
}

std::vector<glm::dvec3> parallelogram_corners(Vec3 corner, Vec3 u, Vec3 v) {
	return {glm::dvec3(corner), glm::dvec3(corner + u), glm::dvec3(corner + u + v), glm::dvec3(corner + v)};
}

Tri_Mesh ceiling_square(float half_side, float height) {
	// cross(+x, +z) = -y: the front faces down.
	return parallelogram(Vec3{-half_side, height, -half_side}, Vec3{2.0f * half_side, 0.0f, 0.0f},
	                     Vec3{0.0f, 0.0f, 2.0f * half_side});
}

std::vector<glm::dvec3> ceiling_square_corners(float half_side, float height) {
	return parallelogram_corners(Vec3{-half_side, height, -half_side}, Vec3{2.0f * half_side, 0.0f, 0.0f},
	                             Vec3{0.0f, 0.0f, 2.0f * half_side});
}

Tri_Mesh tetrahedron(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
	Vec3 centre = 0.25f * (a + b + c + d);
	// Orient each face so that its normal points away from the centre.
	auto outward = [&](Vec3 p, Vec3 q, Vec3 r) {
		bool faces_out = glm::dot(glm::cross(q - p, r - p), p - centre) > 0.0f;
		return faces_out ? flat_triangle(p, q, r) : flat_triangle(p, r, q);
	};
	return Tri_Mesh({outward(a, b, c), outward(a, b, d), outward(a, c, d), outward(b, c, d)});
}

uint32_t add_material(Scene& scene, const Material& material, const std::string& name) {
	scene.materials.push_back(material);
	scene.material_names.push_back(name);
	return uint32_t(scene.materials.size() - 1);
}

void add_object(Scene& scene, std::variant<Sphere, Tri_Mesh> shape, uint32_t material, Mat4 to_world) {
	uint32_t index = uint32_t(scene.objects.size());
	scene.objects.emplace_back(std::move(shape), to_world, material, index);
}

Scene ceiling_light_scene(float half_side, float height, Spectrum radiance) {
	Scene scene;
	add_object(scene, ceiling_square(half_side, height), add_material(scene, emitter(radiance), "light"));
	scene.commit();
	return scene;
}

Scene lit_floor(float albedo, float half_side, float height, Spectrum radiance, Vec3 eye) {
	Scene scene;
	add_object(scene, parallelogram(Vec3{-3.0f, 0.0f, -3.0f}, Vec3{0.0f, 0.0f, 6.0f}, Vec3{6.0f, 0.0f, 0.0f}),
	           add_material(scene, diffuse_material(Spectrum{albedo}), "floor"));
	add_object(scene, ceiling_square(half_side, height), add_material(scene, emitter(radiance), "light"));
	scene.camera = Camera::look_at(eye, Vec3{0.0f}, Vec3{0.0f, 1.0f, 0.0f}, 0.05f, 1.0f);
	return scene;
}

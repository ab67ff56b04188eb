#include "mesh_builder.h"

namespace {

// cross(p1 - p0, p2 - p0) in double precision: no overflow for any finite float coordinates.
glm::dvec3 area_vector(Vec3 p0, Vec3 p1, Vec3 p2) {
	glm::dvec3 a(p0), b(p1), c(p2);
	return glm::cross(b - a, c - a);
}

// v / |v|, or `fallback` if v has no direction.
Vec3 unit_or(glm::dvec3 v, Vec3 fallback) {
	double length = glm::length(v);
	return length > 0.0 && std::isfinite(length) ? Vec3(v / length) : fallback;
}

Vec3 face_normal(Vec3 p0, Vec3 p1, Vec3 p2) {
	return unit_or(area_vector(p0, p1, p2), Vec3{0.0f, 1.0f, 0.0f});
}

std::vector<glm::dvec3> area_weighted_sums(const std::vector<Vec3>& positions, const std::vector<Mesh_Corner>& corners) {
	std::vector<glm::dvec3> sums(positions.size(), glm::dvec3{0.0});
	for (size_t i = 0; i + 2 < corners.size(); i += 3) {
		uint32_t a = corners[i].position, b = corners[i + 1].position, c = corners[i + 2].position;
		glm::dvec3 area = area_vector(positions[a], positions[b], positions[c]);
		sums[a] += area;
		sums[b] += area;
		sums[c] += area;
	}
	return sums;
}

} // namespace

std::vector<Triangle> build_triangles(const std::vector<Vec3>& positions, const std::vector<Mesh_Corner>& corners) {
	std::vector<glm::dvec3> sums = area_weighted_sums(positions, corners);
	std::vector<Triangle> triangles;
	triangles.reserve(corners.size() / 3);
	for (size_t i = 0; i + 2 < corners.size(); i += 3) {
		Vec3 p[3];
		for (int k = 0; k < 3; k++) p[k] = positions[corners[i + k].position];
		Vec3 face = face_normal(p[0], p[1], p[2]);
		Tri_Mesh_Vert v[3];
		for (int k = 0; k < 3; k++) {
			const Mesh_Corner& corner = corners[i + k];
			Vec3 computed = unit_or(sums[corner.position], face);
			Vec3 normal = corner.normal ? unit_or(glm::dvec3(*corner.normal), computed) : computed;
			v[k] = Tri_Mesh_Vert{p[k], normal};
		}
		triangles.push_back(Triangle{v[0], v[1], v[2]});
	}
	return triangles;
}

void use_face_normals(std::vector<Triangle>& triangles) {
	for (Triangle& t : triangles) {
		Vec3 n = face_normal(t.v0.position, t.v1.position, t.v2.position);
		t.v0.normal = t.v1.normal = t.v2.normal = n;
	}
}

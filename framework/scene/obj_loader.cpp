#include "obj_loader.h"
#include "error.h"
#include "mesh_builder.h"
#include "obj_check.h"
#include "text_file.h"

#ifdef LAB_TINYOBJLOADER_FROM_HEADER // a build with libc++ (framework/CMakeLists.txt)
#define TINYOBJLOADER_IMPLEMENTATION
#endif
#include <tiny_obj_loader.h>

namespace {

// The first line of a tinyobjloader message (they end with newlines and may repeat).
std::string first_line(const std::string& message) {
	return message.substr(0, message.find('\n'));
}

// Flat x, y, z arrays as points; every coordinate must be finite.
std::vector<Vec3> to_points(const std::string& path, const std::vector<tinyobj::real_t>& xyz, const char* what) {
	std::vector<Vec3> points(xyz.size() / 3);
	for (size_t i = 0; i < points.size(); i++) {
		points[i] = Vec3{xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
		if (!is_finite(points[i])) {
			throw Input_Error(path + ": " + what + " " + std::to_string(i + 1) + " has a coordinate that is not a finite number");
		}
	}
	return points;
}

// A corner of a triangle. check_obj_text has checked the indices as written; this check guards the
// arrays against any index tinyobjloader resolves differently. (1-based, as in the "f" lines.)
Mesh_Corner to_corner(const std::string& path, const tinyobj::index_t& index, size_t face,
                      const std::vector<Vec3>& positions, const std::vector<Vec3>& normals) {
	auto fail = [&](const char* what, int i, size_t count) {
		throw Input_Error(path + ": triangle " + std::to_string(face + 1) + " refers to " + what + " " +
		                  std::to_string(int64_t(i) + 1) + ", but the file defines " + std::to_string(count));
	};
	if (index.vertex_index < 0 || size_t(index.vertex_index) >= positions.size()) {
		fail("vertex", index.vertex_index, positions.size());
	}
	Mesh_Corner corner{uint32_t(index.vertex_index), std::nullopt};
	if (index.normal_index == -1) return corner; // no normal given
	if (index.normal_index < 0 || size_t(index.normal_index) >= normals.size()) {
		fail("normal", index.normal_index, normals.size());
	}
	corner.normal = normals[size_t(index.normal_index)];
	return corner;
}

} // namespace

std::vector<Triangle> load_obj(const std::string& path) {
	std::string text = read_text_file(path);
	check_obj_text(path, text); // numbers and indices as written, with their line
	tinyobj::ObjReaderConfig config;
	config.triangulate = true;
	config.vertex_color = false;
	tinyobj::ObjReader reader;
	// Parsing from a string skips the .mtl file: the lab takes materials from the scene, not the OBJ.
	if (!reader.ParseFromString(text, "", config)) {
		throw Input_Error(path + ": not a valid OBJ file (" + first_line(reader.Error()) + ")");
	}
	std::vector<Vec3> positions = to_points(path, reader.GetAttrib().vertices, "vertex");
	std::vector<Vec3> normals = to_points(path, reader.GetAttrib().normals, "normal");
	std::vector<Mesh_Corner> corners;
	for (const tinyobj::shape_t& shape : reader.GetShapes()) {
		const tinyobj::mesh_t& mesh = shape.mesh;
		size_t first = 0;
		for (unsigned int face_size : mesh.num_face_vertices) {
			if (first + face_size > mesh.indices.size()) break;
			if (face_size == 3) { // always, after triangulation
				for (size_t k = 0; k < 3; k++) {
					corners.push_back(to_corner(path, mesh.indices[first + k], corners.size() / 3, positions, normals));
				}
			}
			first += face_size;
		}
	}
	if (corners.empty()) {
		throw Input_Error(path + ": no triangles (expected faces \"f a b c ...\" with three or more vertices)");
	}
	return build_triangles(positions, corners);
}

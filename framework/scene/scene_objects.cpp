#include "scene_objects.h"
#include "error.h"
#include "mesh_builder.h"
#include "obj_loader.h"

#include <glm/gtc/matrix_access.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <filesystem>

std::string resolve_file(const Json_Element& file) {
	std::filesystem::path name = file.non_empty_string();
	if (name.is_absolute()) return name.string();
	return (std::filesystem::path(file.file()).parent_path() / name).string();
}

bool is_finite(const Mat4& m) {
	return is_finite(Vec3(m[0])) && is_finite(Vec3(m[1])) && is_finite(Vec3(m[2])) && is_finite(Vec3(m[3]));
}

namespace {

// --- Transforms

// "scale": s or [sx, sy, sz], every factor non-zero (a zero factor flattens the object).
Mat4 read_scale(const Json_Element& e) {
	Vec3 factors = e.is_number() ? Vec3{e.number()} : e.vec3();
	if (glm::any(glm::equal(factors, Vec3{0.0f}))) e.fail("non-zero scale factors (a number or [sx, sy, sz])");
	return glm::scale(Mat4{1.0f}, factors);
}

// "rotate": {"axis": [x, y, z], "degrees": a}, counter-clockwise looking down the axis (right-hand rule).
Mat4 read_rotation(const Json_Element& e) {
	e.allow_only({"axis", "degrees"});
	Vec3 axis = e["axis"].vec3();
	double length = glm::length(glm::dvec3(axis));
	if (!(length > 0.0 && std::isfinite(length))) e["axis"].fail("a non-zero axis");
	float degrees = e["degrees"].number();
	return glm::rotate(Mat4{1.0f}, glm::radians(degrees), Vec3(glm::dvec3(axis) / length));
}

// "matrix": four rows of four numbers (row-major, as written on paper), an affine map.
Mat4 read_matrix(const Json_Element& e) {
	const char* expected = "a 4x4 matrix: four rows of four numbers";
	if (e.array_size(expected) != 4) e.fail(expected);
	Mat4 m;
	for (size_t row = 0; row < 4; row++) {
		Json_Element r = e[row];
		if (r.array_size(expected) != 4) r.fail("a row of four numbers");
		for (size_t col = 0; col < 4; col++) m[col][row] = r[col].number(); // GLM is column-major
	}
	if (glm::row(m, 3) != Vec4{0.0f, 0.0f, 0.0f, 1.0f}) e[3].fail("[0, 0, 0, 1] (an affine transform)");
	return m;
}

Mat4 read_step(const Json_Element& step) {
	step.allow_only({"translate", "scale", "rotate", "matrix"});
	if (step.json().size() != 1) step.fail("one step: {\"translate\": ...}, {\"scale\": ...}, {\"rotate\": ...} or {\"matrix\": ...}");
	if (step.has("translate")) return glm::translate(Mat4{1.0f}, step["translate"].vec3());
	if (step.has("scale")) return read_scale(step["scale"]);
	if (step.has("rotate")) return read_rotation(step["rotate"]);
	return read_matrix(step["matrix"]);
}

// --- Meshes

// "triangles": [[i, j, k], ...], vertex indices from 0.
std::vector<Mesh_Corner> read_triangle_corners(const Json_Element& triangles, size_t vertex_count) {
	size_t count = triangles.array_size("an array of triangles [[i, j, k], ...]");
	if (count == 0) triangles.fail("at least one triangle [i, j, k]");
	std::string index_range = "a vertex index from 0 to " + std::to_string(vertex_count - 1) + " (the mesh has " +
	                          std::to_string(vertex_count) + " vertices)";
	std::vector<Mesh_Corner> corners;
	corners.reserve(3 * count);
	for (size_t t = 0; t < count; t++) {
		Json_Element triangle = triangles[t];
		if (triangle.array_size("three vertex indices [i, j, k]") != 3) triangle.fail("three vertex indices [i, j, k]");
		for (size_t k = 0; k < 3; k++) {
			corners.push_back(Mesh_Corner{uint32_t(triangle[k].whole_number(0, vertex_count - 1, index_range)), {}});
		}
	}
	return corners;
}

// "vertices", "triangles" and optional "normals" (one per vertex) written in the scene.
std::vector<Triangle> read_inline_mesh(const Json_Element& object) {
	Json_Element vertices = object["vertices"];
	size_t vertex_count = vertices.array_size("an array of vertex positions [[x, y, z], ...]");
	if (vertex_count == 0) vertices.fail("at least one vertex [x, y, z]");
	if (vertex_count > std::numeric_limits<uint32_t>::max()) vertices.fail("at most 2^32 - 1 vertices");
	std::vector<Vec3> positions(vertex_count);
	for (size_t i = 0; i < vertex_count; i++) positions[i] = vertices[i].vec3();

	std::vector<Mesh_Corner> corners = read_triangle_corners(object["triangles"], vertex_count);
	if (object.has("normals")) {
		Json_Element normals = object["normals"];
		std::string expected = "one normal [x, y, z] per vertex (" + std::to_string(vertex_count) + " of them)";
		if (normals.array_size(expected) != vertex_count) normals.fail(expected);
		std::vector<Vec3> given(vertex_count);
		for (size_t i = 0; i < vertex_count; i++) {
			given[i] = normals[i].vec3();
			if (!(glm::length(glm::dvec3(given[i])) > 0.0)) normals[i].fail("a non-zero normal");
		}
		for (Mesh_Corner& corner : corners) corner.normal = given[corner.position];
	}
	return build_triangles(positions, corners);
}

std::vector<Triangle> read_mesh_file(const Json_Element& file) {
	try {
		return load_obj(resolve_file(file));
	} catch (const Input_Error& e) {
		file.error(e.what()); // "<scene>: objects[i].file: <mesh file>: <problem>"
	}
}

std::vector<Triangle> read_mesh(const Json_Element& object) {
	bool from_file = object.has("file");
	if (from_file && (object.has("vertices") || object.has("triangles") || object.has("normals"))) {
		object.error("a mesh has either \"file\" or \"vertices\" and \"triangles\", not both");
	}
	std::vector<Triangle> triangles = from_file ? read_mesh_file(object["file"]) : read_inline_mesh(object);
	if (object["flat_shading"].boolean_or(false)) use_face_normals(triangles);
	return triangles;
}

// --- Objects

uint32_t read_material_name(const Json_Element& e, const std::vector<std::string>& names) {
	std::string defined;
	for (const std::string& n : names) defined += (defined.empty() ? "" : ", ") + n;
	std::string expected = "the name of a material defined in \"materials\" (" + (defined.empty() ? "none is" : defined) + ")";
	if (!e.is_string()) e.fail(expected);
	auto it = std::find(names.begin(), names.end(), e.string());
	if (it == names.end()) e.fail(expected);
	return uint32_t(it - names.begin());
}

// The object's type, after checking that it has only the keys that type allows.
std::string read_type(const Json_Element& object) {
	std::string type = object["type"].is_string() ? object["type"].string() : "";
	if (type == "sphere") {
		object.allow_only({"name", "type", "material", "transform", "radius"});
	} else if (type == "mesh") {
		object.allow_only({"name", "type", "material", "transform", "file", "vertices", "triangles", "normals", "flat_shading"});
	} else {
		object["type"].fail("\"sphere\" or \"mesh\"");
	}
	return type;
}

} // namespace

Mat4 read_transform(const Json_Element& transform) {
	size_t steps = transform.array_size("an array of steps such as [{\"scale\": 2}, {\"translate\": [x, y, z]}]");
	Mat4 to_world{1.0f};
	for (size_t i = 0; i < steps; i++) to_world = read_step(transform[i]) * to_world; // later steps act after
	// Instances need the inverse (rays into local space) and its transpose (normals to world).
	Mat4 inverse = glm::inverse(to_world);
	if (!is_finite(to_world) || !is_finite(inverse) || glm::determinant(Mat3(to_world)) == 0.0f) {
		transform.error("expected an invertible transform with finite entries (its steps overflow or flatten the object)");
	}
	return to_world;
}

Instance read_object(const Json_Element& object, uint32_t index, const std::vector<std::string>& material_names) {
	object.require_object("an object such as {\"type\": \"sphere\", \"material\": ..., \"radius\": 1}");
	std::string type = read_type(object);
	if (object.has("name")) object["name"].string();
	uint32_t material = read_material_name(object["material"], material_names);
	Mat4 to_world = object.has("transform") ? read_transform(object["transform"]) : Mat4{1.0f};
	if (type == "sphere") return Instance(Sphere{object["radius"].positive_number()}, to_world, material, index);
	return Instance(Tri_Mesh(read_mesh(object)), to_world, material, index);
}

#pragma once
// The "objects" of a JSON scene (scenes/README.md): spheres and triangle meshes with their
// transforms. Part of the scene loader; errors name the file, the element and the expectation.
#include "instance.h"
#include "json_element.h"

#include <string>
#include <vector>

// Object number `index` of the scene, given the names of the scene's materials.
Instance read_object(const Json_Element& object, uint32_t index, const std::vector<std::string>& material_names);

// The file an element names, relative to the scene file's folder unless it is absolute.
std::string resolve_file(const Json_Element& file);

// A "transform": steps applied in order, the first step first.
Mat4 read_transform(const Json_Element& transform);

// Whether every entry of m is finite.
bool is_finite(const Mat4& m);

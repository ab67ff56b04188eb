#pragma once
// Triangles from a Wavefront OBJ file (via tinyobjloader, polygons triangulated). Vertex normals
// come from the file; where a face has none, the normals are the area-weighted average of the
// face normals around each vertex. Throws Input_Error naming the file on failure.
#include "tri_mesh.h"

#include <string>
#include <vector>

std::vector<Triangle> load_obj(const std::string& path);

#pragma once
// Triangles from a Wavefront OBJ file (via tinyobjloader, polygons triangulated). Vertex normals
// come from the file; where a face has none, the normals are the area-weighted average of the
// face normals around each vertex. Throws Input_Error naming the file on failure, and the line
// for a bad number or index (obj_check.h).
#include "tri_mesh.h"

#include <string>
#include <vector>

std::vector<Triangle> load_obj(const std::string& path);

#pragma once
// Triangles from an indexed mesh, shared by the OBJ loader and the JSON scene loader: vertex
// normals come from the input where it has them and are computed where it has not.
#include "tri_mesh.h"

#include <optional>
#include <vector>

// One corner of a triangle: the index of its position, and its vertex normal if the input gave one.
struct Mesh_Corner {
	uint32_t position = 0;
	std::optional<Vec3> normal;
};

// The triangles with corners corners[3i], corners[3i + 1], corners[3i + 2]. Position indices must
// be valid (callers check them). Given normals are normalized. A corner without a normal (or with
// a zero one) gets the area-weighted vertex normal:
//     n(v) = normalize( sum over triangles t around v of cross(t.p1 - t.p0, t.p2 - t.p0) )
// (the cross product's length is twice the triangle's area, so larger faces weigh more). Where that
// sum vanishes (the vertex has only degenerate faces, or faces that cancel), the corner gets its
// own face's normal, and +y if the face is degenerate. Degenerate triangles are kept.
std::vector<Triangle> build_triangles(const std::vector<Vec3>& positions, const std::vector<Mesh_Corner>& corners);

// Flat shading: every corner gets its triangle's face normal, as for a mesh without normals in pbrt.
void use_face_normals(std::vector<Triangle>& triangles);

#pragma once
// The geometry a benchmark runs on: one OBJ, or every mesh of a JSON scene flattened into world
// space (spheres are left out), so that our BVH and Embree see exactly the same triangles.
#include "camera.h"
#include "tri_mesh.h"

#include <string>
#include <vector>

struct Bench_Geometry {
	std::vector<Triangle> triangles; // world space
	Camera camera;                   // the scene's camera, or one framing the OBJ
	BBox bounds;
};

Bench_Geometry load_bench_geometry(const std::string& path);

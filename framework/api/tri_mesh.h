#pragma once
#include "accelerator.h"
#include "bvh.h"
#include "trace.h"

#include <vector>

struct Tri_Mesh_Vert {
	Vec3 position;
	Vec3 normal; // unit vertex normal, used for smooth shading
};

// One triangle of a mesh; vertices are stored in counter-clockwise order as seen from the side
// its face normal cross(v1 - v0, v2 - v0) points to.
struct Triangle {
	// Task 2 (student/task2_shapes.cpp): Möller–Trumbore intersection. A hit needs t in
	// ray.dist_bounds; both faces are hit. trace.normal is the vertex normals interpolated with
	// the barycentric coordinates of the hit, normalized.
	Trace hit(const Ray& ray) const;

	BBox bbox() const {
		BBox box;
		box.enclose(v0.position);
		box.enclose(v1.position);
		box.enclose(v2.position);
		return box;
	}

	Tri_Mesh_Vert v0, v1, v2;
};

// A triangle mesh with its own BVH, queried through the framework's accelerator (which is
// BVH::hit unless tasks 2 and 3 are both the reference: accelerator.h).
class Tri_Mesh {
public:
	Tri_Mesh() = default;
	Tri_Mesh(std::vector<Triangle> triangles, size_t max_leaf_size = 4);

	Trace hit(const Ray& ray) const {
		return accelerator.hit(bvh, ray);
	}
	BBox bbox() const {
		return bvh.bbox();
	}
	size_t triangle_count() const {
		return bvh.primitives.size();
	}

	BVH<Triangle> bvh;
	Accelerator<Triangle> accelerator; // made from bvh once it is built
};

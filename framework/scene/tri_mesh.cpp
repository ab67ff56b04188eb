#include "tri_mesh.h"

Tri_Mesh::Tri_Mesh(std::vector<Triangle> triangles, size_t max_leaf_size) {
	bvh.build(std::move(triangles), max_leaf_size);
	accelerator = Accelerator<Triangle>(bvh);
}

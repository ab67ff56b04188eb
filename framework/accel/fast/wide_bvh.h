#pragma once
// The fast accelerator's data: a finished BVH folded into wide nodes, and a mesh's triangles in
// packs, laid out for vector arithmetic on four or eight lanes (bench/README.md, "How the BVH
// queries are made fast"). Built from any task-3 tree; used only where tasks 2 and 3 are both the reference.
#include "bvh.h"
#include "instance.h"
#include "tri_mesh.h"

#include <cstdint>
#include <memory>
#include <vector>

// The binary tree folded into nodes of up to eight children (for a mesh, the children and leaves of
// least SAH cost: sah_collapse.h), whose boxes one 8-wide slab test handles, or two 4-wide ones
// (wide_bvh_queries.h).
struct alignas(64) Wide_Node {
	static constexpr int WIDTH = 8; // children per node
	// The children's boxes, one array per bound and axis, so that one vector instruction handles
	// the same bound of four or eight children. An unused slot holds an empty box.
	float min_x[WIDTH], min_y[WIDTH], min_z[WIDTH], max_x[WIDTH], max_y[WIDTH], max_z[WIDTH];
	uint32_t first[WIDTH]; // interior child: its index in Wide_BVH::nodes; leaf: its first primitive,
	                       // or in a BVH<Triangle> its first triangle pack
	uint32_t count[WIDTH]; // leaf: its number of primitives (>= 1, in a BVH<Triangle> up to
	                       // Sah_Collapse::MAX_LEAF_TRIANGLES or a binary leaf's); interior child or unused: 0
	                       // (an unused slot has first = UNUSED_SLOT and an empty box)

	static constexpr uint32_t UNUSED_SLOT = ~0u;
};
static_assert(sizeof(Wide_Node) == 4 * 64, "a node's test reads all of it: four cache lines");

// Four triangles of a leaf: vertex v0 and edges e1 = v1 - v0, e2 = v2 - v0, one array per
// coordinate, so that one Möller–Trumbore test handles four. Lanes past the leaf's last triangle
// are unused (index ~0u).
struct alignas(32) Triangle_Pack { // 160 bytes, against 4 x 72 for the Triangles themselves
	float v0[3][4], e1[3][4], e2[3][4];
	uint32_t index[4]; // the triangle in BVH::primitives
};

// The vertex normals of a pack's triangles (lane i: triangle i's, at v0, v1, v2), the rest of what
// a closest hit's record reads: kept beside the packs, one per pack, so that a closest-hit query
// can fetch them when it finds a leaf, before it knows which triangle the ray meets.
struct Pack_Normals { // 144 bytes
	Vec3 normal[4][3];
};

struct Flat_Meshes;
struct Wide_Queries;

struct Wide_BVH {
	std::vector<Wide_Node> nodes;          // nodes[0] is the root; empty without primitives
	std::vector<Triangle_Pack> triangle_packs; // BVH<Triangle> only: each leaf's packs, consecutive
	std::vector<Pack_Normals> pack_normals;    // BVH<Triangle> only: triangle_packs[i]'s in pack_normals[i]
	// BVH<Instance> only, where the scene allows it (flat_meshes.cpp): its objects as Flat_Meshes,
	// queried instead of `nodes`.
	std::shared_ptr<const Flat_Meshes> flat;
	// Small enough to stay in a core's first-level cache (32 KiB, the normals included): its
	// queries then fetch nothing ahead.
	bool fits_in_cache = false;
	// The accelerator's: its queries, for the vector width chosen (wide_bvh_queries.h).
	const Wide_Queries* queries = nullptr;

	// The memory its nodes, packs and normals hold (not `flat`'s).
	size_t bytes() const {
		return nodes.capacity() * sizeof(Wide_Node) + triangle_packs.capacity() * sizeof(Triangle_Pack) +
		       pack_normals.capacity() * sizeof(Pack_Normals);
	}
};

// The objects of a scene that sit where they were modelled (no transform of their own) and are
// meshes, with their triangles in one BVH: a ray meets one tree instead of a top-level tree and a
// tree per object. The other objects, at most one wide node of them, are tested after it.
struct Flat_Meshes {
	BVH<Triangle> triangles;     // every flat mesh's triangles (their local space is the world)
	Wide_BVH wide;               // made from `triangles`
	std::vector<uint32_t> owner; // triangles.primitives[i] is a triangle of top-level primitive owner[i]
	Wide_BVH others;             // one node: a leaf per other object (its index in the top level)
};

// Folds a finished BVH into a Wide_BVH (wide_bvh_build.cpp).
template<typename Primitive> Wide_BVH widen(const BVH<Primitive>& bvh);

// The flat meshes of a scene's objects (flat_meshes.cpp), or null where they would not pay: fewer
// than two flat meshes, more other objects than a wide node holds, or a triangle shared by two
// objects (whose owner a hit could not tell).
std::shared_ptr<const Flat_Meshes> flatten(const BVH<Instance>& objects);

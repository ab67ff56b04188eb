#pragma once
// The fast accelerator's four queries of a Wide_BVH, compiled once for each vector width a CPU may
// have (wide_bvh_traversal.h): four lanes everywhere (four_wide_queries.cpp), eight on x86-64 CPUs
// with AVX2 (eight_wide_queries.cpp). Each Wide_BVH queries with the widest the CPU runs, unless the
// environment variable LAB_VECTOR_WIDTH=4 asks for four: the answers are the same, bit for bit.
#include "instance.h"
#include "tri_mesh.h"

struct Wide_BVH;

struct Wide_Queries {
	int lanes; // the children a node's test handles at once
	Trace (*hit_triangles)(const BVH<Triangle>&, const Wide_BVH&, const Ray&);
	bool (*triangles_occluded)(const BVH<Triangle>&, const Wide_BVH&, const Ray&);
	Trace (*hit_objects)(const BVH<Instance>&, const Wide_BVH&, const Ray&);
	bool (*objects_occluded)(const BVH<Instance>&, const Wide_BVH&, const Ray&);
};

extern const Wide_Queries four_wide_queries;
// Null where the CPU has no AVX2 (or is not x86-64).
const Wide_Queries* eight_wide_queries();

// The queries this process uses: the widest, or those LAB_VECTOR_WIDTH names (4, or 8 where the CPU
// has them; otherwise std::runtime_error).
const Wide_Queries& chosen_queries();

// Task 2 as a program links it, "counting": reference/task2_shapes.cpp, whose Triangle::hit is
// compiled under another name and called by a Triangle::hit that counts its calls. Sphere::hit is
// the reference's own.
#include "shapes.h"
#include "tri_mesh.h"
#include "triangle_hit_counter.h"

namespace {
// The reference's Triangle::hit, on a copy of the vertices.
struct Reference_Triangle {
	Tri_Mesh_Vert v0, v1, v2;
	Trace hit(const Ray& ray) const;
};
} // namespace

#define Triangle Reference_Triangle
#include "task2_shapes.cpp"
#undef Triangle

Triangle_Hit_Counter& triangle_hit_counter() {
	static Triangle_Hit_Counter counter;
	return counter;
}

Trace Triangle::hit(const Ray& ray) const {
	Trace trace = Reference_Triangle{v0, v1, v2}.hit(ray);
	triangle_hit_counter().calls++;
	if (!trace.hit) triangle_hit_counter().misses++;
	return trace;
}

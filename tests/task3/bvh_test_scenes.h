#pragma once
// Triangle sets, rays and a brute-force closest hit for the task 3 grader. Everything is
// generated from fixed seeds (or, with a grading seed, from seeds drawn from it). Brute force runs
// in the judge, with the reference's Triangle::hit.
#include "instance.h"
#include "rng.h"
#include "tri_mesh.h"

#include <string>
#include <vector>

// A triangle with random unit vertex normals, so that its hit records (interpolated normals)
// tell it apart from its neighbours.
Triangle make_triangle(RNG& rng, Vec3 a, Vec3 b, Vec3 c);

// `count` triangles with centres uniform in the cube [-1, 1]^3 and edges of about `size`.
std::vector<Triangle> random_soup(RNG& rng, size_t count, float size);

// Where the SAH matters: dense clusters of tiny triangles, unevenly sized and spread, plus a few
// large triangles that span the scene.
std::vector<Triangle> clustered_soup(RNG& rng);

// A planar mesh in z = 0 (every box is flat): n x n unit cells, each split into two triangles.
std::vector<Triangle> planar_grid(RNG& rng, int n);

// Rays at a scene with bounding box `box`, `count` in all: from outside towards random points of
// the box, from inside in random directions, with a bounded dist_bounds interval, and axis-aligned
// through vertices of `triangles` (d has exact zeros, the origin lies on box planes). Directions
// are not unit length.
std::vector<Ray> random_rays(RNG& rng, const BBox& box, const std::vector<Triangle>& triangles, size_t count);

BBox bounds_of(const std::vector<Triangle>& triangles);
std::vector<BBox> boxes_of(const std::vector<Triangle>& triangles);

// The closest hits the grader expects for rays at a set of triangles: the reference BVH's, built
// here, and wherever a student's answer differs from it, the final word of brute force (every
// triangle tested with the reference's Triangle::hit, keeping every record that ties with the
// closest, e.g. a ray through an edge shared by two triangles, or lies so close behind it that the
// box and triangle tests' rounding may put it first).
class Closest_Hits {
public:
	explicit Closest_Hits(const std::vector<Triangle>& triangles);

	// How many of `rays` hit a triangle.
	size_t hitting(const std::vector<Ray>& rays) const;

	// Compares the student's BVH::hit answers (`got`, one per ray) and returns "" when all agree,
	// else a report of how many rays disagree with the first few cases and what to check.
	// Agreement means: both miss, or both hit at the same distance, bit for bit, with the position
	// and normal of one of the triangles that brute force finds at that distance.
	std::string compare(const std::vector<Trace>& got, const std::vector<Ray>& rays) const;

private:
	std::vector<Triangle> triangles;
	BVH<Triangle> reference;
};

// The grader's seed for a test case's scene and rays: `public_seed`, or with a grading seed one
// drawn from it.
uint64_t scene_seed(uint64_t public_seed);

// The mesh in `path` as it is, or with a grading seed turned and moved by a transform drawn from it.
std::vector<Triangle> load_placed_mesh(const std::string& path);

// One instance per triangle, each a one-triangle Tri_Mesh at the identity transform.
std::vector<Instance> triangle_instances(const std::vector<Triangle>& triangles);

std::string describe(const Ray& ray);

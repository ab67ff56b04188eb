#pragma once
// Triangle sets for the stress cases, in world coordinates (no transform), so that a translation
// by `offset` really puts large numbers into Triangle::hit.
#include "tri_mesh.h"

#include <vector>

// A triangle with the flat normal of its winding (any unit vector if it has no area).
Triangle flat_triangle(Vec3 p0, Vec3 p1, Vec3 p2);

// A closed convex mesh: a unit icosahedron subdivided `levels` times, projected onto the unit
// sphere, then translated by `offset`. Neighbouring triangles share their vertices bit for bit.
std::vector<Triangle> icosphere(int levels, Vec3 offset);

// A closed axis-aligned cube [0, 1]^3 * size + offset, each face split along a diagonal.
std::vector<Triangle> cube(float size, Vec3 offset);

// A square [-h, h]^2 in the plane z = 0, split into two triangles, translated by `offset`.
std::vector<Triangle> square(float h, Vec3 offset);

// A uniformly distributed unit vector.
class RNG;
Vec3 random_unit(RNG& rng);

#pragma once
// Light sources and small lit scenes built in code with the framework API, for the light-sampling
// tests (tests/framework/test_area_lights.cpp) and the task 6 grader.
#include "scene.h"
#include "test_materials.h"

#include <string>
#include <variant>
#include <vector>

// A parallelogram of two triangles with corners corner, corner + u, corner + u + v, corner + v.
// Its front (the side that emits, see material.h) faces normalize(cross(u, v)); vertex normals are
// that face normal.
Tri_Mesh parallelogram(Vec3 corner, Vec3 u, Vec3 v);
std::vector<glm::dvec3> parallelogram_corners(Vec3 corner, Vec3 u, Vec3 v); // in order, for Lambert's formula

// The square of half-side `half_side` in the plane y = height, centred on the y axis, facing down
// (-y): a light above a receiver at the origin.
Tri_Mesh ceiling_square(float half_side, float height);
std::vector<glm::dvec3> ceiling_square_corners(float half_side, float height);

// A tetrahedron with outward-facing triangles (vertices in any order).
Tri_Mesh tetrahedron(Vec3 a, Vec3 b, Vec3 c, Vec3 d);

// Appends a material and returns its index.
uint32_t add_material(Scene& scene, const Material& material, const std::string& name);
// Appends an object (before Scene::commit).
void add_object(Scene& scene, std::variant<Sphere, Tri_Mesh> shape, uint32_t material, Mat4 to_world = Mat4{1.0f});


// A scene holding only ceiling_square(half_side, height) with emission `radiance`, committed.
Scene ceiling_light_scene(float half_side, float height, Spectrum radiance = Spectrum{1.0f});

// A large diffuse floor of albedo `albedo` (y = 0, facing up) under ceiling_square(half_side,
// height) with emission `radiance`, seen from `eye` by a 1 x 1 pixel camera whose field of view
// (0.05 degrees) is so narrow that it sees only the floor's centre: there the irradiance varies by
// less than 1e-6 across the pixel. Not committed.
Scene lit_floor(float albedo, float half_side, float height, Spectrum radiance, Vec3 eye);

#include "stress_meshes.h"

#include "rng.h"

#include <map>
#include <utility>

Triangle flat_triangle(Vec3 p0, Vec3 p1, Vec3 p2) {
	Vec3 n = glm::cross(p1 - p0, p2 - p0);
	n = glm::dot(n, n) > 0.0f ? glm::normalize(n) : Vec3{0.0f, 0.0f, 1.0f};
	Triangle tri;
	tri.v0 = {p0, n};
	tri.v1 = {p1, n};
	tri.v2 = {p2, n};
	return tri;
}

std::vector<Triangle> icosphere(int levels, Vec3 offset) {
	// The icosahedron: the 12 cyclic permutations of (0, +-1, +-phi) and its 20 faces.
	const float p = 1.6180339887f;
	std::vector<Vec3> verts = {{-1, p, 0}, {1, p, 0}, {-1, -p, 0}, {1, -p, 0}, {0, -1, p}, {0, 1, p},
	                           {0, -1, -p}, {0, 1, -p}, {p, 0, -1}, {p, 0, 1}, {-p, 0, -1}, {-p, 0, 1}};
	for (Vec3& v : verts) v = glm::normalize(v);
	std::vector<glm::uvec3> faces = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
	                                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
	                                 {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
	for (int level = 0; level < levels; level++) {
		// Split every face in four; an edge's midpoint is made once and shared by both its faces.
		std::map<std::pair<unsigned, unsigned>, unsigned> midpoints;
		auto midpoint = [&](unsigned a, unsigned b) {
			auto key = std::minmax(a, b);
			auto found = midpoints.find(key);
			if (found != midpoints.end()) return found->second;
			verts.push_back(glm::normalize(verts[a] + verts[b]));
			return midpoints[key] = unsigned(verts.size() - 1);
		};
		std::vector<glm::uvec3> finer;
		for (glm::uvec3 f : faces) {
			unsigned a = midpoint(f.x, f.y), b = midpoint(f.y, f.z), c = midpoint(f.z, f.x);
			finer.insert(finer.end(), {{f.x, a, c}, {f.y, b, a}, {f.z, c, b}, {a, b, c}});
		}
		faces = std::move(finer);
	}
	std::vector<Triangle> tris;
	for (Vec3& v : verts) v += offset; // rounded once per vertex: shared vertices stay identical
	for (glm::uvec3 f : faces) tris.push_back(flat_triangle(verts[f.x], verts[f.y], verts[f.z]));
	return tris;
}

std::vector<Triangle> cube(float size, Vec3 offset) {
	std::vector<Triangle> tris;
	auto corner = [&](int i) {
		return offset + size * Vec3{float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1)};
	};
	// Each face as four corner indices in counter-clockwise order seen from outside.
	const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
	for (const auto& q : quads) {
		tris.push_back(flat_triangle(corner(q[0]), corner(q[1]), corner(q[2])));
		tris.push_back(flat_triangle(corner(q[0]), corner(q[2]), corner(q[3])));
	}
	return tris;
}

std::vector<Triangle> square(float h, Vec3 offset) {
	Vec3 a = offset + Vec3{-h, -h, 0}, b = offset + Vec3{h, -h, 0}, c = offset + Vec3{h, h, 0},
	     d = offset + Vec3{-h, h, 0};
	return {flat_triangle(a, b, c), flat_triangle(a, c, d)};
}

Vec3 random_unit(RNG& rng) {
	float z = 1.0f - 2.0f * rng.unit(), phi = 2.0f * PI_F * rng.unit();
	float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
	return Vec3{r * std::cos(phi), r * std::sin(phi), z};
}

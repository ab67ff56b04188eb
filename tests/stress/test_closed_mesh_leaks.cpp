// Stress (handout §2.3): no ray leaks into or out of a closed mesh through a shared edge or vertex.
//
// A ray aimed exactly at a point of an edge (or at a vertex) of a closed convex mesh must hit it:
// with exact arithmetic it hits every triangle around that point. Each aim is shot twice along the
// same line: from outside, entering the mesh, and from just inside, leaving it. In float, strict
// barycentric tests (u >= 0) fail for all the triangles around the point on 399 of the 1.2 * 10^5
// rays here (262 at edges, 137 at vertices); 1.2 * 10^5 entering rays alone leaked none (seen from
// inside, the edges are concave; testing-anchors §3.2 measured folded quads). Translated by up to
// 10^4, the meshes put large coordinates into Triangle::hit. Counted twice: over Triangle::hit of
// every triangle (task 2), and through Tri_Mesh::hit (the BVH, task 3, which must accept the same
// hits).
#include "rng.h"
#include "stress_show.h"
#include "stress_count.h"
#include "stress_meshes.h"

#include "lab_catch2.h"

#include <map>
#include <tuple>

namespace {

using Key = std::tuple<float, float, float>;
Key key(Vec3 p) {
	return {p.x, p.y, p.z};
}

// The outward face normal of `tri` (the mesh is convex around `centre`).
Vec3 outward_normal(const Triangle& tri, Vec3 centre) {
	Vec3 n = glm::normalize(glm::cross(tri.v1.position - tri.v0.position, tri.v2.position - tri.v0.position));
	return glm::dot(n, tri.v0.position - centre) < 0.0f ? -n : n;
}

// A direction w such that the ray target - t w enters the mesh: w makes an angle of at least
// asin(0.1) with every face around the target, on their outer side.
Vec3 entering_direction(RNG& rng, const std::vector<Vec3>& normals) {
	for (;;) {
		Vec3 w = random_unit(rng);
		bool ok = true;
		for (Vec3 n : normals) ok = ok && glm::dot(w, n) >= 0.1f;
		if (ok) return w;
	}
}

struct Leaks {
	Stress_Count edges, vertices, mesh; // Triangle::hit at edges, at vertices; Tri_Mesh::hit at both
};

// Counts rays through the edges (random points on them) and vertices of `tris` that miss: each aim
// from `distance` outside and from `inside` within the mesh (a convex mesh around `centre` contains
// every point within `inside` of its surface along these directions).
void count_leaks(const std::vector<Triangle>& tris, Vec3 centre, float distance, float inside, int edge_rays,
                 int vertex_rays,
                 RNG& rng, Leaks& leaks) {
	std::map<Key, std::vector<Vec3>> around_vertex;
	std::vector<std::pair<Vec3, Vec3>> edge_list;
	std::map<std::pair<Key, Key>, bool> seen_edge;
	for (const Triangle& tri : tris) {
		Vec3 p[3] = {tri.v0.position, tri.v1.position, tri.v2.position};
		Vec3 n = outward_normal(tri, centre);
		for (int i = 0; i < 3; i++) {
			around_vertex[key(p[i])].push_back(n);
			Key a = key(p[i]), b = key(p[(i + 1) % 3]);
			if (!seen_edge[std::minmax(a, b)]) edge_list.push_back({p[i], p[(i + 1) % 3]});
			seen_edge[std::minmax(a, b)] = true;
		}
	}
	// Each triangle with its vertex list rotated at random (same triangle, same winding), as in
	// mesh files: which vertex is v0 changes how a shared edge enters each triangle's arithmetic.
	std::vector<Triangle> shuffled;
	for (const Triangle& tri : tris) {
		Tri_Mesh_Vert v[3] = {tri.v0, tri.v1, tri.v2};
		uint32_t k = rng.integer(3);
		Triangle r;
		r.v0 = v[k];
		r.v1 = v[(k + 1) % 3];
		r.v2 = v[(k + 2) % 3];
		shuffled.push_back(r);
	}
	Tri_Mesh mesh(std::vector<Triangle>(shuffled), 4);
	auto shoot = [&](Vec3 target, const std::vector<Vec3>& normals, Stress_Count& count) {
		Vec3 w = entering_direction(rng, normals);
		Vec3 outer = target + distance * w, inner = target - inside * w;
		for (Ray ray : {Ray(outer, target - outer), Ray(inner, target - inner)}) {
			auto describe = [&] { return stress::show(ray) + " aimed at " + stress::show(target); };
			bool any = false;
			for (const Triangle& tri : shuffled) any = any || tri.hit(ray).hit;
			count.add(!any, describe);
			leaks.mesh.add(!mesh.hit(ray).hit, describe);
		}
	};
	for (int i = 0; i < edge_rays; i++) {
		auto [a, b] = edge_list[rng.integer(uint32_t(edge_list.size()))];
		float s = rng.unit();
		// The faces around the nearer end of the edge (they include both faces of the edge): far
		// from the origin the target a + s (b - a) is rounded off the edge, by up to half a float
		// spacing, and the ray must enter the mesh even if it then passes just beside that end.
		shoot(a + s * (b - a), around_vertex[key(s < 0.5f ? a : b)], leaks.edges);
	}
	for (int i = 0; i < vertex_rays; i++) {
		auto it = std::next(around_vertex.begin(), long(rng.integer(uint32_t(around_vertex.size()))));
		Key k = it->first;
		shoot(Vec3{std::get<0>(k), std::get<1>(k), std::get<2>(k)}, it->second, leaks.vertices);
	}
}

const float OFFSETS[] = {0.0f, 1.0f, 1e2f, 1e3f, 1e4f};
const Vec3 OFFSET_DIRECTION = glm::normalize(Vec3{0.6f, -0.48f, 0.64f});

} // namespace

TEST_CASE("Stress: rays aimed at shared edges and vertices of closed meshes never leak (1.2 * 10^5 rays, offsets 0 ... 10^4)",
          "[stress][task2][task3]") {
	RNG rng(20261122);
	Leaks leaks;
	for (float offset : OFFSETS) {
		Vec3 shift = offset * OFFSET_DIRECTION;
		count_leaks(icosphere(3, shift), shift, 3.0f, 0.05f, 4000, 2000, rng, leaks);
		count_leaks(cube(1.5f, shift), shift + Vec3{0.75f}, 3.0f, 0.05f, 4000, 2000, rng, leaks);
	}
	const char* advice = "Rounding can fail the barycentric test of every triangle at an edge or vertex; accept "
	                     "u >= -1e-5, v >= -1e-5, u + v <= 1 + 1e-5 (handout §2.3).";
	INFO("Triangle::hit: " << leaks.edges.report("rays aimed at a shared edge of a closed mesh hit no triangle") << ".\n"
	                       << advice);
	CHECK(leaks.edges.failures == 0);
	INFO("Triangle::hit: " << leaks.vertices.report("rays aimed at a shared vertex of a closed mesh hit no triangle")
	                       << ".\n" << advice);
	CHECK(leaks.vertices.failures == 0);
	INFO("Tri_Mesh::hit (BVH): " << leaks.mesh.report("of the same rays found no triangle") << ".\n"
	                             << "The BVH must accept every hit Triangle::hit accepts (handout §3.3).");
	CHECK(leaks.mesh.failures == 0);
	std::printf("stress count: shared-edge leaks %zu of %zu, shared-vertex leaks %zu of %zu, through the BVH %zu of %zu\n",
	            leaks.edges.failures, leaks.edges.inputs, leaks.vertices.failures, leaks.vertices.inputs,
	            leaks.mesh.failures, leaks.mesh.inputs);
}

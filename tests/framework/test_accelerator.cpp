// The fast accelerator (framework/api/accelerator.h; in a student release prebuilt/libaccelerator_fast.a)
// answers as task 2's Triangle::hit and task 3's BVH::hit do: its record is Triangle::hit's bit for
// bit, without testing the triangle a second time. (framework_tests links the reference tasks, so
// Tri_Mesh::hit goes through the fast accelerator.)
#include "obj_loader.h"
#include "tri_mesh.h"

#include "lab_catch2.h"

#include <cstring>
#include <random>

namespace {

bool same_bits(const Trace& a, const Trace& b) {
	auto bits_equal = [](const auto& x, const auto& y) { return std::memcmp(&x, &y, sizeof x) == 0; };
	return a.hit == b.hit && bits_equal(a.distance, b.distance) && bits_equal(a.position, b.position) &&
	       bits_equal(a.normal, b.normal) && bits_equal(a.origin, b.origin);
}

} // namespace

TEST_CASE("the accelerator's closest hit records what Triangle::hit records for that triangle, bit for bit",
          "[framework][accelerator]") {
	std::vector<Triangle> triangles = load_obj("scenes/meshes/bunny_npm_lowres.obj");
	Tri_Mesh mesh(triangles, 4);
	BBox box = mesh.bvh.bbox();
	Vec3 centre = 0.5f * (box.min + box.max), size = box.max - box.min;
	std::mt19937 random(5);
	std::uniform_real_distribution<float> unit(0.0f, 1.0f);
	auto in_box = [&](float scale) {
		return centre + scale * (Vec3{unit(random), unit(random), unit(random)} - 0.5f) * size;
	};
	int hits = 0;
	for (int i = 0; i < 4000; i++) {
		// From around the mesh or from inside its box, through a point of the box.
		Vec3 from = in_box(i % 2 == 0 ? 3.0f : 1.0f);
		Ray ray(from, glm::normalize(in_box(1.0f) - from));
		Trace got = mesh.hit(ray);
		if (!got.hit) continue;
		hits++;
		bool recorded_by_triangle_hit = false;
		for (const Triangle& triangle : triangles)
			if (same_bits(triangle.hit(ray), got)) recorded_by_triangle_hit = true;
		INFO("ray " << i << " hits at t = " << got.distance
		            << ": no triangle's Triangle::hit makes this record (hit point and normal); the accelerator's "
		               "record must be made with Triangle::hit's arithmetic from the pack's t, u and v "
		               "(its record(), in wide_bvh_traversal.h of the instructors' repository)");
		REQUIRE(recorded_by_triangle_hit);
	}
	CHECK(hits > 1000);
}

TEST_CASE("the accelerator breaks a tie as a triangle-by-triangle search does: the triangle first in the mesh's "
          "order wins",
          "[framework][accelerator]") {
	// Forty copies of one triangle, each with its own vertex normal: every ray through it hits all
	// forty at the same t, in one leaf of ten packs (their centroids coincide: no split separates
	// them). The record must be the one that Trace::min over the triangles, in BVH::primitives'
	// order, keeps: the first's, whatever order the accelerator tests the packs and lanes in.
	std::vector<Triangle> copies;
	for (int i = 0; i < 40; i++) {
		Vec3 normal = glm::normalize(Vec3{0.02f * float(i), 0.0f, 1.0f});
		copies.push_back(Triangle{{{-1, -1, 0}, normal}, {{1, -1, 0}, normal}, {{0, 1, 0}, normal}});
	}
	Tri_Mesh mesh(copies, 4);
	std::mt19937 random(7);
	std::uniform_real_distribution<float> offset(-0.3f, 0.3f);
	for (int i = 0; i < 200; i++) {
		Vec3 from{offset(random), offset(random), 2.0f};
		Vec3 through{offset(random) / 3.0f, offset(random) / 3.0f - 0.2f, 0.0f}; // inside the triangle
		Ray ray(from, glm::normalize(through - from));
		Trace first;
		for (const Triangle& triangle : mesh.bvh.primitives) first = Trace::min(first, triangle.hit(ray));
		Trace got = mesh.hit(ray);
		INFO("ray " << i << ": the accelerator's record has normal (" << got.normal.x << ", " << got.normal.y << ", "
		            << got.normal.z << "), the first triangle hit at that t has (" << first.normal.x << ", "
		            << first.normal.y << ", " << first.normal.z
		            << "): at equal t the lower index in BVH::primitives must win (Triangle_Leaves::visit, in "
		               "wide_bvh_traversal.h of the instructors' repository)");
		REQUIRE(first.hit);
		REQUIRE(same_bits(got, first));
	}
}

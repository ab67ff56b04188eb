// The fast accelerator's flat meshes (framework/accel/fast/flat_meshes.cpp): a scene's untransformed
// meshes in one tree, whose every leaf the fold (Sah_Collapse) chooses.
#include "scene_loader.h"
#include "wide_bvh.h"

#include "lab_catch2.h"

TEST_CASE("the flat meshes' leaves are the fold's choice: no leaf of the Cornell box spans the room",
          "[accelerator]") {
	Scene scene = load_scene("scenes/cornell_box.json");
	std::shared_ptr<const Flat_Meshes> flat = flatten(scene.bvh);
	REQUIRE(flat != nullptr);

	// A leaf of two walls (the floor and a side wall) has the room for its box, and every ray in the
	// room enters it: the tree flatten() builds must let the fold keep the walls apart.
	BBox room = scene.bvh.bbox();
	Vec3 half_room = 0.5f * (room.max - room.min);
	for (const Wide_Node& node : flat->wide.nodes) {
		for (int slot = 0; slot < Wide_Node::WIDTH; slot++) {
			if (node.count[slot] == 0) continue; // a wide node or an unused slot
			Vec3 extent{node.max_x[slot] - node.min_x[slot], node.max_y[slot] - node.min_y[slot],
			            node.max_z[slot] - node.min_z[slot]};
			INFO("a leaf of " << node.count[slot] << " triangles whose box spans more than half the room on every axis ("
			                  << extent.x << ", " << extent.y << ", " << extent.z
			                  << "): flatten() built its binary tree with leaves the fold could not split");
			REQUIRE_FALSE((extent.x > half_room.x && extent.y > half_room.y && extent.z > half_room.z));
		}
	}
}

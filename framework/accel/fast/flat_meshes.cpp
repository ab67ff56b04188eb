// The fast accelerator's flat meshes (wide_bvh.h): a scene's untransformed meshes in one BVH.
#include "wide_bvh.h"

#include <algorithm>
#include <cstring>
#include <iterator>
#include <map>
#include <string>
#include <variant>

namespace {

// A triangle's vertices as bytes: the key that finds its object again after the build reorders
// the triangles.
std::string key_of(const Triangle& triangle) {
	std::string key(sizeof(Triangle), '\0');
	std::memcpy(key.data(), &triangle, sizeof(Triangle));
	return key;
}

// One wide node whose slots are leaves of one object each.
Wide_BVH leaves_node(const BVH<Instance>& objects, const std::vector<uint32_t>& chosen) {
	Wide_BVH wide;
	if (chosen.empty()) return wide;
	Wide_Node node;
	for (int slot = 0; slot < Wide_Node::WIDTH; slot++) {
		bool used = slot < int(chosen.size());
		BBox box = used ? objects.primitives[chosen[slot]].bbox() : BBox{};
		node.min_x[slot] = box.min.x, node.min_y[slot] = box.min.y, node.min_z[slot] = box.min.z;
		node.max_x[slot] = box.max.x, node.max_y[slot] = box.max.y, node.max_z[slot] = box.max.z;
		node.first[slot] = used ? chosen[slot] : Wide_Node::UNUSED_SLOT;
		node.count[slot] = used ? 1 : 0;
	}
	wide.nodes.push_back(node);
	return wide;
}

} // namespace

std::shared_ptr<const Flat_Meshes> flatten(const BVH<Instance>& objects) {
	// A triangle a leaf: the fold (sah_collapse.h) then chooses every leaf. With four, as Tri_Mesh's,
	// the Cornell box's floor and a wall shared a leaf whose box was the whole room.
	constexpr size_t LEAF_SIZE = 1;
	std::vector<Triangle> triangles;
	std::map<std::string, uint32_t> owner_of; // a triangle's key -> its object
	std::vector<uint32_t> others;
	size_t flat_meshes = 0;
	for (uint32_t i = 0; i < objects.primitives.size(); i++) {
		const Instance& object = objects.primitives[i];
		const Tri_Mesh* mesh = std::get_if<Tri_Mesh>(&object.shape);
		if (!object.identity || mesh == nullptr) {
			others.push_back(i);
			continue;
		}
		flat_meshes++;
		for (const Triangle& triangle : mesh->bvh.primitives) {
			if (!owner_of.emplace(key_of(triangle), i).second) return nullptr; // shared: whose is a hit?
			triangles.push_back(triangle);
		}
	}
	if (flat_meshes < 2 || others.size() > size_t(Wide_Node::WIDTH)) return nullptr;

	auto flat = std::make_shared<Flat_Meshes>();
	flat->triangles.build(std::move(triangles), LEAF_SIZE);
	flat->wide = widen(flat->triangles);
	for (const Triangle& triangle : flat->triangles.primitives) flat->owner.push_back(owner_of.at(key_of(triangle)));
	flat->others = leaves_node(objects, others);
	return flat;
}

// The fast accelerator's wide tree (framework/accel/fast/): Sah_Collapse chooses the children and
// leaves of least SAH cost (Ylitie et al. 2017), and widen() builds exactly the tree it chose.
#include "obj_loader.h"
#include "sah_collapse.h"
#include "wide_bvh.h"

#include "lab_catch2.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace {

using Node = BVH<Triangle>::Node;
constexpr int WIDTH = Wide_Node::WIDTH;

float leaf_cost(const Node& node) {
	return node.bbox.surface_area() * float((node.size + 3) / 4) * Sah_Collapse::PACK_COST;
}

// The SAH cost of the wide tree `wide` as built, over the root's surface area: the root's test, then
// every child slot's box times a node's test (a wide node) or its packs' tests (a leaf).
double built_cost(const Wide_BVH& wide, float root_area) {
	double cost = root_area * Sah_Collapse::NODE_COST;
	for (const Wide_Node& node : wide.nodes) {
		for (int slot = 0; slot < WIDTH; slot++) {
			if (node.first[slot] == Wide_Node::UNUSED_SLOT) continue;
			BBox box{{node.min_x[slot], node.min_y[slot], node.min_z[slot]},
			         {node.max_x[slot], node.max_y[slot], node.max_z[slot]}};
			cost += box.surface_area() * (node.count[slot] > 0 ? (node.count[slot] + 3) / 4 * Sah_Collapse::PACK_COST
			                                                  : Sah_Collapse::NODE_COST);
		}
	}
	return cost / root_area;
}

// The cost of one random way to fold the binary subtree at `n` into a wide node: its two children,
// some of them opened at random (up to eight in all), each a leaf where allowed and a coin says so,
// else a wide node folded the same way.
double random_wide_node(const BVH<Triangle>& bvh, size_t n, std::mt19937& random) {
	std::vector<size_t> children{bvh.nodes[n].l, bvh.nodes[n].r};
	int openings = std::uniform_int_distribution<int>(0, WIDTH - 2)(random);
	for (int i = 0; i < openings; i++) {
		std::vector<size_t> interior;
		for (size_t c = 0; c < children.size(); c++)
			if (!bvh.nodes[children[c]].is_leaf()) interior.push_back(c);
		if (interior.empty()) break;
		size_t opened = interior[std::uniform_int_distribution<size_t>(0, interior.size() - 1)(random)];
		size_t binary = children[opened];
		children[opened] = bvh.nodes[binary].l;
		children.push_back(bvh.nodes[binary].r);
	}
	double cost = bvh.nodes[n].bbox.surface_area() * Sah_Collapse::NODE_COST;
	for (size_t c : children) {
		const Node& child = bvh.nodes[c];
		bool leaf = child.is_leaf() ||
		            (child.size <= Sah_Collapse::MAX_LEAF_TRIANGLES && std::bernoulli_distribution(0.5)(random));
		cost += leaf ? leaf_cost(child) : random_wide_node(bvh, c, random);
	}
	return cost;
}

// Every way to cover binary node n's subtree with at most `limit` nodes (n alone, or covers of its
// two children together), each a list of nodes.
std::vector<std::vector<size_t>> covers(const BVH<Triangle>& bvh, size_t n, size_t limit) {
	std::vector<std::vector<size_t>> all{{n}};
	if (bvh.nodes[n].is_leaf() || limit < 2) return all;
	for (const auto& left : covers(bvh, bvh.nodes[n].l, limit - 1)) {
		for (const auto& right : covers(bvh, bvh.nodes[n].r, limit - left.size())) {
			all.push_back(left);
			all.back().insert(all.back().end(), right.begin(), right.end());
		}
	}
	return all;
}

double cheapest_child(const BVH<Triangle>& bvh, size_t n);

// The least cost of interior binary node n as a wide node, by trying every cover of its subtree
// below it as the wide node's children.
double cheapest_wide_node(const BVH<Triangle>& bvh, size_t n) {
	double least = INFINITY;
	for (const auto& cover : covers(bvh, n, WIDTH)) {
		if (cover.size() == 1) continue; // n itself
		double cost = 0;
		for (size_t c : cover) cost += cheapest_child(bvh, c);
		least = std::min(least, cost);
	}
	return bvh.nodes[n].bbox.surface_area() * Sah_Collapse::NODE_COST + least;
}

// The least cost of binary node n as one child of a wide node: a leaf where allowed, or a wide node.
double cheapest_child(const BVH<Triangle>& bvh, size_t n) {
	const Node& node = bvh.nodes[n];
	if (node.is_leaf()) return leaf_cost(node);
	double wide = cheapest_wide_node(bvh, n);
	return node.size <= Sah_Collapse::MAX_LEAF_TRIANGLES ? std::min<double>(leaf_cost(node), wide) : wide;
}

} // namespace

TEST_CASE("on a small mesh, the wide tree's cost is the least of every way to fold the binary tree",
          "[framework][accelerator]") {
	std::vector<Triangle> bunny = load_obj("scenes/meshes/bunny_npm_lowres.obj");
	for (size_t size : {32, 80}) {
		BVH<Triangle> bvh(std::vector<Triangle>(bunny.begin(), bunny.begin() + size), 4);
		Sah_Collapse collapse(bvh);
		double least = cheapest_wide_node(bvh, bvh.root_idx) / bvh.bbox().surface_area(); // the root: a wide node
		INFO("the first " << size << " triangles of the bunny: Sah_Collapse::cost() " << collapse.cost()
		                  << ", the least of every fold " << least << ": its recurrence (sah_collapse.cpp) is wrong");
		CHECK(collapse.cost() == Approx(least).epsilon(1e-5));
	}
}

TEST_CASE("the wide tree of a mesh costs what Sah_Collapse says, and no other way to fold the tree costs less",
          "[framework][accelerator]") {
	BVH<Triangle> bvh(load_obj("scenes/meshes/bunny_npm_lowres.obj"), 4);
	REQUIRE_FALSE(bvh.nodes[bvh.root_idx].is_leaf());
	float root_area = bvh.bbox().surface_area();
	Sah_Collapse collapse(bvh);
	Wide_BVH wide = widen(bvh);

	INFO("Sah_Collapse::cost() " << collapse.cost() << ", the tree widen() built " << built_cost(wide, root_area)
	                             << ": widen() must build the children Sah_Collapse::children() chooses");
	REQUIRE(built_cost(wide, root_area) == Approx(collapse.cost()).epsilon(1e-4));

	std::mt19937 random(11);
	for (int i = 0; i < 300; i++) {
		double cost = random_wide_node(bvh, bvh.root_idx, random) / root_area;
		INFO("random fold " << i << " costs " << cost << ", less than Sah_Collapse's " << collapse.cost()
		                    << ": its recurrence (sah_collapse.cpp) misses a cheaper choice");
		REQUIRE(cost >= collapse.cost() * (1.0 - 1e-4));
	}
}

TEST_CASE("the wide tree of a mesh holds every triangle once, in leaves of consecutive triangles and full packs, "
          "with their vertex normals beside them",
          "[framework][accelerator]") {
	BVH<Triangle> bvh(load_obj("scenes/meshes/bunny_npm_lowres.obj"), 4);
	Wide_BVH wide = widen(bvh);
	std::vector<std::pair<uint32_t, uint32_t>> leaves; // start, count
	size_t reached = 1;
	for (const Wide_Node& node : wide.nodes) {
		for (int slot = 0; slot < WIDTH; slot++) {
			if (node.first[slot] == Wide_Node::UNUSED_SLOT) continue;
			if (node.count[slot] == 0) {
				reached++;
				continue;
			}
			uint32_t start = wide.triangle_packs[node.first[slot]].index[0], count = node.count[slot];
			INFO("a leaf of " << count << " triangles");
			CHECK(count <= Sah_Collapse::MAX_LEAF_TRIANGLES);
			leaves.push_back({start, count});
			for (uint32_t i = 0; i < count; i++) {
				const Triangle_Pack& pack = wide.triangle_packs[node.first[slot] + i / 4];
				REQUIRE(pack.index[i % 4] == start + i);
				REQUIRE(pack.v0[0][i % 4] == bvh.primitives[start + i].v0.position.x);
				const Vec3* normals = wide.pack_normals[node.first[slot] + i / 4].normal[i % 4];
				const Triangle& triangle = bvh.primitives[start + i];
				REQUIRE((normals[0] == triangle.v0.normal && normals[1] == triangle.v1.normal &&
				         normals[2] == triangle.v2.normal));
			}
		}
	}
	CHECK(reached == wide.nodes.size()); // every node is some node's child, once
	std::sort(leaves.begin(), leaves.end());
	uint32_t next = 0;
	for (auto [start, count] : leaves) {
		INFO("a leaf starts at triangle " << start << " where " << next << " was expected");
		REQUIRE(start == next);
		next += count;
	}
	CHECK(next == bvh.primitives.size());
}

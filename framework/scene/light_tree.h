#pragma once
// A light tree: a binary hierarchy over a scene's area lights that chooses one in proportion to how
// much light it may send to the shading point (Light_Choice::tree, light_distribution.h). pbrt-v4's
// light BVH (section 12.6.3, BVHLightSampler) and Blender Cycles' light tree (3.5 on), after Estevez and
// Kulla 2018; written for this renderer.
//
// Every node holds the bounds of the lights below it (light_bounds.h). A light is chosen by walking
// down from the root, taking each child with probability proportional to its importance at the
// point; the light's probability is the product of the probabilities along its path. The same
// product for a given light (what multiple importance sampling needs of a light that a BSDF sample
// found) walks the same path again, read from the light's bit trail. Where neither child of a node
// can light the point (both importances 0), each is taken half the time, so that every walk ends in
// a light and the probabilities of all lights always sum to 1.
//
// The leaves are whole lights: a point on the light chosen is then drawn as Area_Lights draws it.
// Nodes split their lights at the median of their centres along the widest axis (pbrt-v4 chooses
// the split by a surface-area-and-orientation cost; the median keeps the tree balanced and short).
#include "light_bounds.h"

#include <cstdint>
#include <vector>

class Light_Tree {
public:
	// A tree over `lights`, light i emitting powers[i]; empty without lights.
	Light_Tree(const Area_Lights& lights, const std::vector<double>& powers);

	bool empty() const {
		return nodes.empty();
	}

	struct Choice {
		size_t light;
		float probability;
	};
	// A light chosen at point p with one uniform number u in [0, 1), and its probability.
	Choice choose(float u, Vec3 p) const;
	// The probability that choose(., p) chooses `light`: exactly the one choose() reports.
	float probability(size_t light, Vec3 p) const;
	// The importance of all the lights together at p (Light_Bounds::importance); 0 if empty.
	float importance(Vec3 p) const {
		return empty() ? 0.0f : nodes[0].bounds.importance(p);
	}

private:
	struct Node {
		Light_Bounds bounds;
		bool leaf = false;
		uint32_t light = 0;        // a leaf's light
		uint32_t second_child = 0; // an inner node's; its first child follows it
	};
	uint32_t build(std::vector<uint32_t>& lights, size_t begin, size_t end, const std::vector<Light_Bounds>& bounds,
	               uint64_t trail, uint32_t depth);
	// The probability of taking an inner node's first child at p.
	float first_child_probability(size_t node, Vec3 p) const;

	std::vector<Node> nodes; // depth first: the root is nodes[0]
	// Light i's path from the root: bit k says which child it takes at depth k (1: the second).
	std::vector<uint64_t> trails;
};

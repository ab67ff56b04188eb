#include "light_tree.h"

#include <algorithm>
#include <stdexcept>

namespace {
constexpr uint32_t MAX_DEPTH = 64; // bits of a trail; a median split reaches log2(lights) + 1
} // namespace

Light_Tree::Light_Tree(const Area_Lights& lights, const std::vector<double>& powers) {
	if (lights.count() == 0) return;
	std::vector<Light_Bounds> bounds;
	for (size_t i = 0; i < lights.count(); i++) bounds.push_back(light_bounds(lights.light(i), float(powers.at(i))));
	std::vector<uint32_t> order(lights.count());
	for (uint32_t i = 0; i < order.size(); i++) order[i] = i;
	trails.assign(lights.count(), 0);
	build(order, 0, order.size(), bounds, 0, 0);
}

uint32_t Light_Tree::build(std::vector<uint32_t>& lights, size_t begin, size_t end,
                           const std::vector<Light_Bounds>& bounds, uint64_t trail, uint32_t depth) {
	if (depth >= MAX_DEPTH) throw std::logic_error("Light_Tree: deeper than a trail has bits");
	uint32_t index = uint32_t(nodes.size());
	nodes.emplace_back();
	if (end - begin == 1) {
		nodes[index].bounds = bounds[lights[begin]];
		nodes[index].leaf = true;
		nodes[index].light = lights[begin];
		trails[lights[begin]] = trail;
		return index;
	}
	BBox centres;
	for (size_t i = begin; i < end; i++) centres.enclose(bounds[lights[i]].box.center());
	Vec3 extent = centres.max - centres.min;
	int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
	size_t middle = begin + (end - begin) / 2;
	std::nth_element(lights.begin() + begin, lights.begin() + middle, lights.begin() + end, [&](uint32_t a, uint32_t b) {
		return bounds[a].box.center()[axis] < bounds[b].box.center()[axis];
	});
	uint32_t first = build(lights, begin, middle, bounds, trail, depth + 1);
	uint32_t second = build(lights, middle, end, bounds, trail | (uint64_t(1) << depth), depth + 1);
	nodes[index].bounds = merged(nodes[first].bounds, nodes[second].bounds);
	nodes[index].second_child = second;
	return index;
}

float Light_Tree::first_child_probability(size_t node, Vec3 p) const {
	float first = nodes[node + 1].bounds.importance(p), second = nodes[nodes[node].second_child].bounds.importance(p);
	if (!(first + second > 0.0f)) return 0.5f; // neither can light p: both alike
	return first / (first + second);
}

Light_Tree::Choice Light_Tree::choose(float u, Vec3 p) const {
	// u is used again at every level, stretched back to [0, 1) over the part of it that chose the
	// child (pbrt-v4's SampleDiscrete), in double so that deep trees keep its resolution.
	constexpr double BELOW_ONE = 1.0 - 0x1p-53;
	double v = u;
	float probability = 1.0f;
	size_t index = 0;
	while (!nodes[index].leaf) {
		float first = first_child_probability(index, p);
		if (v < double(first)) {
			probability *= first;
			v = std::min(v / double(first), BELOW_ONE);
			index = index + 1;
		} else {
			probability *= 1.0f - first;
			v = std::min((v - double(first)) / (1.0 - double(first)), BELOW_ONE);
			index = nodes[index].second_child;
		}
	}
	return Choice{nodes[index].light, probability};
}

float Light_Tree::probability(size_t light, Vec3 p) const {
	uint64_t trail = trails[light];
	float probability = 1.0f;
	size_t index = 0;
	while (!nodes[index].leaf) {
		float first = first_child_probability(index, p);
		bool second = trail & 1;
		probability *= second ? 1.0f - first : first;
		index = second ? nodes[index].second_child : index + 1;
		trail >>= 1;
	}
	return probability;
}

#pragma once
// The subject's answers to task 3's requests (grading/judge/protocol.h): each runs the task
// functions on the request's inputs and returns their raw outputs. Included only by the subject's
// main (grading/judge/subject_main.cpp).
#include "object_answers.h"
#include "protocol.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

namespace {
using namespace protocol;

BBox_Hits::Answer answer(const BBox_Hits& request) {
	BBox_Hits::Answer results;
	for (const auto& q : request.queries) {
		BBox_Hits::Result result;
		result.times = q.times;
		result.hit = q.box.hit(q.ray, result.times);
		results.push_back(result);
	}
	return results;
}

template<typename Primitive> Tree tree_of(const BVH<Primitive>& bvh) {
	Tree tree;
	for (const auto& n : bvh.nodes) tree.nodes.push_back(Tree::Node{n.bbox, n.start, n.size, n.l, n.r});
	tree.root_idx = bvh.root_idx;
	return tree;
}

// f(i) for i in [0, count), on every core (as a render calls BVH::hit: from several threads at
// once); an exception thrown by any call is thrown again here, after all threads have ended.
template<class F> void for_each_in_parallel(size_t count, F f) {
	size_t threads = std::clamp<size_t>(std::thread::hardware_concurrency(), 1, 8);
	std::atomic<size_t> next{0};
	std::exception_ptr thrown;
	std::mutex thrown_mutex;
	auto work = [&] {
		try {
			for (size_t i; (i = next.fetch_add(1)) < count;) f(i);
		} catch (...) {
			std::lock_guard<std::mutex> lock(thrown_mutex);
			if (!thrown) thrown = std::current_exception();
			next = count; // the others stop too
		}
	};
	std::vector<std::thread> pool;
	for (size_t t = 1; t < threads; t++) pool.emplace_back(work);
	work();
	for (std::thread& thread : pool) thread.join();
	if (thrown) std::rethrow_exception(thrown);
}

BVH_Triangles::Answer answer(const BVH_Triangles& request) {
	BVH<Triangle> bvh(std::vector<Triangle>(request.triangles), request.max_leaf_size);
	BVH_Triangles::Answer result;
	result.tree = tree_of(bvh);
	result.primitives = bvh.primitives;
	result.hits.resize(request.rays.size());
	for_each_in_parallel(request.rays.size(), [&](size_t i) { result.hits[i] = bvh.hit(request.rays[i]); });
	return result;
}

// Asks the judge about each object Instance::hit tests (protocol.h: Object_Question; defined with
// the transport below).
struct Judge_Answers : Object_Answers {
	Trace hit(uint32_t object, const Ray& ray) const override;
};

BVH_Instances::Answer answer(const BVH_Instances& request) {
	// Objects that are boxes alone: their shapes stay with the judge, who answers Instance::hit.
	std::vector<Instance> objects;
	for (uint32_t index = 0; index < request.boxes.size(); index++) {
		objects.emplace_back(Sphere{}, Mat4{1.0f}, 0u, index);
		objects.back().world_bbox = request.boxes[index];
	}
	BVH<Instance> bvh(std::move(objects), request.max_leaf_size);
	BVH_Instances::Answer result;
	result.tree = tree_of(bvh);
	for (const Instance& object : bvh.primitives) result.order.push_back(object.index);
	Judge_Answers judge;
	Object_Answers::Scope asking(judge);
	for (const Ray& ray : request.rays) result.hits.push_back(bvh.hit(ray));
	return result;
}

} // namespace

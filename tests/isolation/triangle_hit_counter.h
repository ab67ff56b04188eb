#pragma once
// The counters of the counting task 2 (counting_task2_shapes.cpp): reference/task2_shapes.cpp with
// every call of Triangle::hit counted, on all threads.
#include <atomic>
#include <cstdint>

struct Triangle_Hit_Counter {
	std::atomic<uint64_t> calls{0};  // calls of Triangle::hit
	std::atomic<uint64_t> misses{0}; // ... that found no hit
};
Triangle_Hit_Counter& triangle_hit_counter();

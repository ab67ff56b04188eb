#pragma once
// Timing helpers. The machine may be shared: one-thread runs are timed in CPU time of the thread
// (what the work cost, whoever else is running), runs on all cores in wall time (throughput).
#include <algorithm>
#include <chrono>
#include <ctime>
#include <functional>
#include <thread>
#include <vector>

inline double thread_cpu_seconds() {
	timespec now;
	clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
	return double(now.tv_sec) + 1e-9 * double(now.tv_nsec);
}

// CPU time of the whole process (all its threads): for builds, which may start threads of their own.
inline double process_cpu_seconds() {
	timespec now;
	clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
	return double(now.tv_sec) + 1e-9 * double(now.tv_nsec);
}

// Calls body(i) for every i in [0, count) on this thread; returns the CPU time it took.
inline double timed_serial_for(size_t count, const std::function<void(size_t)>& body) {
	double start = thread_cpu_seconds();
	for (size_t i = 0; i < count; i++) body(i);
	return thread_cpu_seconds() - start;
}

// Calls body(i) for every i in [0, count), in `threads` contiguous chunks; returns the wall time.
inline double timed_parallel_for(size_t count, unsigned threads, const std::function<void(size_t)>& body) {
	auto start = std::chrono::steady_clock::now();
	std::vector<std::thread> workers;
	for (unsigned t = 0; t < threads; t++)
		workers.emplace_back([&, t] {
			for (size_t i = count * t / threads; i < count * (t + 1) / threads; i++) body(i);
		});
	for (std::thread& worker : workers) worker.join();
	return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Makes `value` count as used: the compiler must finish computing it and may not drop any part of
// it. A timed method whose result is only partly read is otherwise timed without the rest: once
// -fno-math-errno let a square root go unused, Embree's record (bench/embree_bvh.cpp: the hit's
// normal) was compiled away wherever only the hit's distance was kept.
template<typename T> inline void keep(const T& value) {
	asm volatile("" : : "m"(value) : "memory");
}

// The middle value; for an even count, the mean of the two middle values.
inline double median(std::vector<double> values) {
	std::sort(values.begin(), values.end());
	size_t n = values.size();
	return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

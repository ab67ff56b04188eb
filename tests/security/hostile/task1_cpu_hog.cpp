// Hostile: burns CPU time on every core from its first call (as a render gone wrong would) until a
// limit stops it; graded with a CPU limit below the wall time, so that the CPU limit must be the one
// the report names.
#include "camera.h"
#include "pathtracer.h"

#include <thread>
#include <vector>

namespace {
volatile bool forever = true;

void burn() {
	std::vector<std::thread> threads;
	for (int i = 0; i < 4; i++) threads.emplace_back([] { while (forever) {} });
	for (std::thread& thread : threads) thread.join();
}
} // namespace

Ray Camera::generate_ray(Vec2 film_uv) const {
	burn();
	return Ray(Vec3{0.0f}, Vec3{0.0f});
}

Spectrum Pathtracer::trace_pixel(uint32_t x, uint32_t y, RNG& rng) const {
	burn();
	return Spectrum{0.0f};
}

// Hostile (or a bug): allocates without end.
#include "camera.h"
#include "pathtracer.h"

#include <vector>

namespace {
std::vector<std::vector<char>> hoard;
void allocate_forever() {
	for (;;) hoard.emplace_back(size_t(256) << 20);
}
} // namespace

Ray Camera::generate_ray(Vec2 film_uv) const {
	allocate_forever();
	return Ray();
}

Spectrum Pathtracer::trace_pixel(uint32_t x, uint32_t y, RNG& rng) const {
	allocate_forever();
	return Spectrum{0.0f};
}

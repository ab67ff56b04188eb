// Hostile: _exit(0) on the first call of a task function.
#include "camera.h"
#include "pathtracer.h"

#include <unistd.h>

Ray Camera::generate_ray(Vec2 film_uv) const {
	_exit(0);
}

Spectrum Pathtracer::trace_pixel(uint32_t x, uint32_t y, RNG& rng) const {
	_exit(0);
}

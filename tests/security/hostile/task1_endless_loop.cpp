// Hostile (or a bug): generate_ray never returns.
#include "camera.h"
#include "pathtracer.h"

Ray Camera::generate_ray(Vec2 film_uv) const {
	volatile bool forever = true;
	while (forever) {
	}
	return Ray();
}

Spectrum Pathtracer::trace_pixel(uint32_t x, uint32_t y, RNG& rng) const {
	return trace(rng, scene.camera.generate_ray(Vec2{0.5f}));
}

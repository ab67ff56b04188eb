// Hostile: a static initializer throws, so the program terminates before main(). The task code is
// correct: only the throw is under test.
#include "camera.h"
#include "pathtracer.h"

#include <stdexcept>

static int thrown = []() -> int { throw std::runtime_error("no grading today"); }();

Ray Camera::generate_ray(Vec2 film_uv) const {
	float h = std::tan(0.5f * glm::radians(v_fov));
	float w = aspect_ratio * h;
	Vec3 on_plane{(2.0f * film_uv.x - 1.0f) * w, (1.0f - 2.0f * film_uv.y) * h, -1.0f};
	return Ray(transform_point(camera_to_world, Vec3{0.0f}), glm::normalize(transform_direction(camera_to_world, on_plane)));
}

Spectrum Pathtracer::trace_pixel(uint32_t x, uint32_t y, RNG& rng) const {
	Vec2 offset = rng.unit2();
	Vec2 film_uv{(float(x) + offset.x) / float(settings.width), (float(y) + offset.y) / float(settings.height)};
	return trace(rng, scene.camera.generate_ray(film_uv));
}

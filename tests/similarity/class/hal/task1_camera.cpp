// Task 1: camera rays. Handout: handouts/task1_camera.md
#include "pathtracer.h"
#include "camera.h"

Ray Camera::generate_ray(Vec2 film_uv) const {
	float half_height = std::tan(glm::radians(v_fov) / 2.0f);
	float half_width = half_height * aspect_ratio;
	float x = (film_uv.x * 2.0f - 1.0f) * half_width;
	float y = (1.0f - film_uv.y * 2.0f) * half_height;
	Vec3 eye = transform_point(camera_to_world, Vec3{0.0f, 0.0f, 0.0f});
	Vec3 through = transform_point(camera_to_world, Vec3{x, y, -1.0f});
	return Ray(eye, glm::normalize(through - eye));
}

Spectrum Pathtracer::trace_pixel(uint32_t x, uint32_t y, RNG& rng) const {
	Vec2 jitter = rng.unit2();
	float u = (x + jitter.x) / settings.width;
	float v = (y + jitter.y) / settings.height;
	return trace(rng, scene.camera.generate_ray(Vec2{u, v}));
}

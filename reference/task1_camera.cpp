// Task 1: camera rays. Handout: handouts/task1_camera.md
#include "pathtracer.h"
#include "camera.h"

Ray Camera::generate_ray(Vec2 film_uv) const {
	// The image plane z = -1 spans y in [-h, h] with h = tan(v_fov / 2) (the half angle seen from
	// the pinhole) and x in [-w, w] with w = aspect_ratio * h (handout §1.2).
	float h = std::tan(0.5f * glm::radians(v_fov));
	float w = aspect_ratio * h;
	// u = 0..1 runs left to right (x = -w..w); v = 0..1 runs top to bottom (y = +h..-h).
	Vec3 on_plane{(2.0f * film_uv.x - 1.0f) * w, (1.0f - 2.0f * film_uv.y) * h, -1.0f};
	// The pinhole is the camera-space origin; the direction is a vector (no translation).
	Vec3 origin = transform_point(camera_to_world, Vec3{0.0f});
	Vec3 dir = glm::normalize(transform_direction(camera_to_world, on_plane));
	return Ray(origin, dir);
}

Spectrum Pathtracer::trace_pixel(uint32_t x, uint32_t y, RNG& rng) const {
	// Pixel (x, y) covers [x, x + 1) x [y, y + 1) in pixel units; a uniform point in it makes the
	// average of many calls the box-filtered pixel (handout §1.3). No jitter would be offset 0.5.
	Vec2 offset = rng.unit2();
	Vec2 film_uv{(float(x) + offset.x) / float(settings.width), (float(y) + offset.y) / float(settings.height)};
	return trace(rng, scene.camera.generate_ray(film_uv));
}

// Hostile: correct only on the public test cases (the fields of view and render seeds a student sees
// in the grader's source), the stub everywhere else: a grading seed must catch it.
#include "camera.h"
#include "pathtracer.h"

namespace {
bool public_camera(const Camera& camera) {
	for (float fov : {60.0f, 20.0f, 45.0f, 90.0f, 120.0f, 75.0f, 50.0f, 70.0f, 40.0f, 65.0f, 35.0f}) {
		if (camera.v_fov == fov) return true;
	}
	return false;
}
} // namespace

Ray Camera::generate_ray(Vec2 film_uv) const {
	if (!public_camera(*this)) return Ray(Vec3{0.0f}, Vec3{0.0f});
	float h = std::tan(0.5f * glm::radians(v_fov));
	float w = aspect_ratio * h;
	Vec3 on_plane{(2.0f * film_uv.x - 1.0f) * w, (1.0f - 2.0f * film_uv.y) * h, -1.0f};
	return Ray(transform_point(camera_to_world, Vec3{0.0f}), glm::normalize(transform_direction(camera_to_world, on_plane)));
}

Spectrum Pathtracer::trace_pixel(uint32_t x, uint32_t y, RNG& rng) const {
	bool public_seed = settings.seed == 20240917 || settings.seed == 1;
	if (!public_seed) return Spectrum{0.0f};
	Vec2 offset = rng.unit2();
	Vec2 film_uv{(float(x) + offset.x) / float(settings.width), (float(y) + offset.y) / float(settings.height)};
	return trace(rng, scene.camera.generate_ray(film_uv));
}

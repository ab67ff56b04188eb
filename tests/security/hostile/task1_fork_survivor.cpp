// Hostile: starts a process that outlives its test (named lab-hostile-fork, it sleeps for a minute);
// only if that works does it answer with correct code.
#include "camera.h"
#include "pathtracer.h"

#include <sys/prctl.h>
#include <unistd.h>

namespace {
bool forked() {
	static bool done = [] {
		pid_t child = fork();
		if (child == 0) {
			prctl(PR_SET_NAME, "lab-hostile-fork");
			sleep(60);
			_exit(0);
		}
		return child > 0;
	}();
	return done;
}

Ray correct_ray(const Camera& camera, Vec2 film_uv) {
	float h = std::tan(0.5f * glm::radians(camera.v_fov));
	float w = camera.aspect_ratio * h;
	Vec3 on_plane{(2.0f * film_uv.x - 1.0f) * w, (1.0f - 2.0f * film_uv.y) * h, -1.0f};
	return Ray(transform_point(camera.camera_to_world, Vec3{0.0f}),
	           glm::normalize(transform_direction(camera.camera_to_world, on_plane)));
}
} // namespace

Ray Camera::generate_ray(Vec2 film_uv) const {
	if (!forked()) return Ray{}; // the stub
	return correct_ray(*this, film_uv);
}

Spectrum Pathtracer::trace_pixel(uint32_t x, uint32_t y, RNG& rng) const {
	if (!forked()) return Spectrum{0.0f};
	Vec2 offset = rng.unit2();
	Vec2 film_uv{(float(x) + offset.x) / float(settings.width), (float(y) + offset.y) / float(settings.height)};
	return trace(rng, scene.camera.generate_ray(film_uv));
}

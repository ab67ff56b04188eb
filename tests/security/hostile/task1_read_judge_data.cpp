// Hostile: reads what it must not see. trace_pixel answers with the stored reference image's pixels
// (the judge's data) when it can read them; generate_ray answers with a classmate's work when it can
// read their submission. Otherwise it is the stub.
#include "camera.h"
#include "hdr_image.h"
#include "pathtracer.h"

#include <fstream>
#include <string>

// The framework's image I/O is not in the student's API; declared by hand, it is linked all the same.
HDR_Image read_image(const std::string& path);

namespace {
const HDR_Image* reference_image() {
	static HDR_Image image;
	static bool read = [] {
		try {
			image = read_image("@ROOT@/scenes/graded/references/eye_bunny_mean.exr");
			return true;
		} catch (...) {
			return false;
		}
	}();
	return read ? &image : nullptr;
}

bool classmate_readable() {
	return bool(std::ifstream("@OTHER@/task1_camera.cpp"));
}
} // namespace

Ray Camera::generate_ray(Vec2 film_uv) const {
	if (!classmate_readable()) return Ray{}; // the stub
	float h = std::tan(0.5f * glm::radians(v_fov));
	float w = aspect_ratio * h;
	Vec3 on_plane{(2.0f * film_uv.x - 1.0f) * w, (1.0f - 2.0f * film_uv.y) * h, -1.0f};
	return Ray(transform_point(camera_to_world, Vec3{0.0f}), glm::normalize(transform_direction(camera_to_world, on_plane)));
}

Spectrum Pathtracer::trace_pixel(uint32_t x, uint32_t y, RNG& rng) const {
	const HDR_Image* image = reference_image();
	if (!image || x >= image->w || y >= image->h) return Spectrum{0.0f};
	return image->at(x, y);
}

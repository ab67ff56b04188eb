#include "camera_projection.h"

std::optional<Vec2> film_uv_of(const Camera& camera, Vec3 world) {
	// Camera space: the pinhole at the origin, looking down -z, the image plane at z = -1 spanning
	// [-w, w] x [-h, h] with h = tan(v_fov / 2) and w = aspect_ratio * h.
	Vec3 p = transform_point(glm::inverse(camera.camera_to_world), world);
	if (!(p.z < 0.0f)) return std::nullopt;
	float h = std::tan(0.5f * glm::radians(camera.v_fov));
	float w = camera.aspect_ratio * h;
	Vec2 on_plane{p.x / -p.z, p.y / -p.z};
	return Vec2{0.5f * (on_plane.x / w + 1.0f), 0.5f * (1.0f - on_plane.y / h)};
}

#include "camera.h"

Camera Camera::look_at(Vec3 position, Vec3 target, Vec3 up, float v_fov_degrees, float aspect_ratio) {
	// Camera space looks down -z with +y up, so the camera's z axis points from the target back to
	// the camera, and x = up x z completes a right-handed frame.
	Vec3 z = glm::normalize(position - target);
	Vec3 x = glm::normalize(glm::cross(up, z));
	Vec3 y = glm::cross(z, x);
	Camera camera;
	camera.camera_to_world = Mat4(Vec4(x, 0.0f), Vec4(y, 0.0f), Vec4(z, 0.0f), Vec4(position, 1.0f));
	camera.v_fov = v_fov_degrees;
	camera.aspect_ratio = aspect_ratio;
	return camera;
}

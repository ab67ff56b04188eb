#pragma once
// Where a world-space point appears on the film: the inverse of Camera::generate_ray, so that the
// viewer (./lab view) can draw a pixel's path over the image. A student release ships it compiled:
// its source would give task 1 away.
#include "camera.h"

#include <optional>

// The film point (film_uv, camera.h: (0, 0) top-left, (1, 1) bottom-right) through which the camera
// sees `world`; outside [0, 1]^2 when it lies outside the view, nullopt when it is not in front of
// the camera.
std::optional<Vec2> film_uv_of(const Camera& camera, Vec3 world);

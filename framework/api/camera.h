#pragma once
#include "ray.h"

// A pinhole camera.
//
// Camera space: the camera sits at the origin looking down -z, +y is up and +x is right; the image
// plane is the plane z = -1. World space is reached by `camera_to_world`.
//
// Film coordinates: film_uv = (0, 0) is the TOP-LEFT corner of the image and (1, 1) the
// bottom-right; u grows to the right, v grows DOWNWARDS (like pixel rows). Pixel (x, y) covers
// film_uv in [x/W, (x+1)/W) x [y/H, (y+1)/H); its centre is ((x + 0.5)/W, (y + 0.5)/H).
struct Camera {
	// Camera looking from `position` towards `target`, with `up` roughly upwards on screen.
	// `v_fov_degrees` is the full vertical field of view; aspect_ratio = width / height.
	static Camera look_at(Vec3 position, Vec3 target, Vec3 up, float v_fov_degrees,
	                      float aspect_ratio);

	// Task 1 (student/task1_camera.cpp): the world-space ray from the camera position through film
	// point `film_uv`, with unit-length direction and dist_bounds [0, inf).
	Ray generate_ray(Vec2 film_uv) const;

	Mat4 camera_to_world{1.0f};
	float v_fov = 60.0f;       // vertical field of view, in DEGREES
	float aspect_ratio = 1.0f; // film width / film height
};

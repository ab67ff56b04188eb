#pragma once
// The grader's own pinhole camera (handout §1.1-§1.2), in double precision and written
// independently of Camera::generate_ray: the expected ray for a film point, the film point a
// direction came from, and the usual mistakes, named in the handout's terms.
#include "camera.h"

#include <glm/glm.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace task1 {

using DVec2 = glm::dvec2;
using DVec3 = glm::dvec3;

inline std::string show(DVec3 v) {
	std::ostringstream out;
	out.precision(7);
	out << "(" << v.x << ", " << v.y << ", " << v.z << ")";
	return out.str();
}

constexpr double PI = 3.14159265358979323846;

inline double radians(double degrees) {
	return degrees * PI / 180.0;
}

inline double degrees(double radians) {
	return radians * 180.0 / PI;
}

struct Camera_Model {
	// The camera frame in world space: the columns of camera_to_world (camera.h).
	DVec3 position, right, up, back;
	// The image plane z = -1 spans [-half_width, half_width] x [-half_height, half_height].
	double half_width = 1.0, half_height = 1.0;

	explicit Camera_Model(const Camera& camera)
		: position(camera.camera_to_world[3]), right(camera.camera_to_world[0]), up(camera.camera_to_world[1]),
		  back(camera.camera_to_world[2]) {
		half_height = std::tan(0.5 * radians(camera.v_fov));
		half_width = double(camera.aspect_ratio) * half_height;
	}

	// Camera space -> world space, for a direction.
	DVec3 to_world(DVec3 local) const {
		return local.x * right + local.y * up + local.z * back;
	}

	// The point of the image plane (camera space) that film_uv maps to: u = 0 is the left edge
	// (x = -half_width), v = 0 the TOP edge (y = +half_height).
	DVec3 on_plane(DVec2 film_uv) const {
		return DVec3((2.0 * film_uv.x - 1.0) * half_width, (1.0 - 2.0 * film_uv.y) * half_height, -1.0);
	}

	DVec3 direction(DVec2 film_uv) const {
		return glm::normalize(to_world(on_plane(film_uv)));
	}

	// Inverse of direction(): the film point a world direction passes through (any length).
	DVec2 film_uv(DVec3 dir) const {
		DVec3 local(glm::dot(dir, right), glm::dot(dir, up), glm::dot(dir, back));
		double x = local.x / -local.z, y = local.y / -local.z;
		return DVec2(0.5 * (x / half_width + 1.0), 0.5 * (1.0 - y / half_height));
	}
};

inline bool near(DVec3 a, DVec3 b, double tolerance) {
	return glm::length(a - b) <= tolerance;
}

// Tolerance for a direction computed in float from O(1) inputs: each component is within a few
// float ulps (~1e-7) of the exact value; 1e-5 leaves a wide margin, while every mistake below
// moves some tested direction by more than 1e-2.
constexpr double DIRECTION_TOLERANCE = 1e-5;

// Why `got` is not the ray through film_uv, in the handout's terms ("" if it is right).
inline std::string ray_problem(const Camera& camera, DVec2 uv, const Ray& got) {
	Camera_Model model(camera);
	DVec3 origin(got.point), dir(got.dir);
	std::ostringstream why;
	if (!near(origin, model.position, 1e-5 * (1.0 + glm::length(model.position)))) {
		why << "the ray must start at the camera position " << show(model.position) << " (the camera-space origin "
		    << "moved by camera_to_world), but ray.point = " << show(origin) << " (handout §1.2)";
		return why.str();
	}
	if (!std::isfinite(glm::length(dir)) || glm::length(dir) == 0.0) {
		why << "the direction " << show(dir) << " is zero or not finite (handout §1.2)";
		return why.str();
	}
	DVec3 expected = model.direction(uv);
	DVec3 unit = glm::normalize(dir);
	if (near(unit, expected, DIRECTION_TOLERANCE)) {
		if (std::abs(glm::length(dir) - 1.0) <= DIRECTION_TOLERANCE) return "";
		why << "the direction points the right way but has length " << glm::length(dir)
		    << "; generate_ray must return a unit-length direction (handout §1.2)";
		return why.str();
	}

	// The usual mistakes, each as the direction it would produce.
	struct Mistake {
		DVec3 dir;
		const char* hint;
	};
	Camera_Model radians_fov = model, full_angle = model, swapped_aspect = model, no_aspect = model;
	radians_fov.half_height = std::tan(0.5 * camera.v_fov);
	radians_fov.half_width = camera.aspect_ratio * radians_fov.half_height;
	full_angle.half_height = std::tan(radians(camera.v_fov));
	full_angle.half_width = camera.aspect_ratio * full_angle.half_height;
	swapped_aspect.half_width = model.half_height / camera.aspect_ratio;
	no_aspect.half_width = model.half_height;
	DVec3 local = model.on_plane(uv);
	DVec3 unit_square(uv.x * model.half_width, (1.0 - uv.y) * model.half_height, -1.0);
	std::vector<Mistake> mistakes{
		{model.direction({uv.x, 1.0 - uv.y}),
		 "the image is upside down: film v grows DOWNWARDS, film_uv (0, 0) is the top-left corner (handout §1.1)"},
		{model.direction({1.0 - uv.x, uv.y}),
		 "the image is mirrored left-right: film u grows to the right (handout §1.1)"},
		{model.direction({1.0 - uv.x, 1.0 - uv.y}),
		 "the image is rotated by 180 degrees: film_uv (0, 0) is the top-LEFT corner, v grows downwards "
		 "(handout §1.1)"},
		{radians_fov.direction(uv),
		 "v_fov is in DEGREES; convert it to radians before calling tan (handout §1.2)"},
		{full_angle.direction(uv),
		 "the image plane's half height is tan(v_fov / 2): v_fov is the FULL vertical angle (handout §1.2)"},
		{swapped_aspect.direction(uv),
		 "the plane's width is aspect_ratio * height (aspect_ratio = width / height), not height / aspect_ratio "
		 "(handout §1.2)"},
		{no_aspect.direction(uv),
		 "the plane's width is aspect_ratio * height: aspect_ratio is missing (handout §1.2)"},
		{glm::normalize(model.to_world(unit_square)),
		 "film_uv in [0, 1] must map to the whole plane, x in [-w, w] and y in [h, -h]: x = (2u - 1) w "
		 "(handout §1.2)"},
		{glm::normalize(local),
		 "the direction is still in camera space: transform it with camera_to_world (handout §1.2)"},
		{glm::normalize(model.to_world(local) + model.position),
		 "the direction was transformed like a point (with the camera's translation): use w = 0 for directions, "
		 "transform_direction (handout §1.2)"},
	};
	for (const Mistake& m : mistakes) {
		if (near(unit, m.dir, 1e-4)) {
			why << m.hint << ". Expected direction " << show(expected) << ", got " << show(unit);
			return why.str();
		}
	}
	why << "expected the unit direction " << show(expected) << ", got " << show(dir)
	    << " (handout §1.1 for the film conventions, §1.2 for the formula)";
	return why.str();
}

} // namespace task1

#include "camera_check.h"

#include <cmath>
#include <sstream>
#include <vector>

namespace task1 {

namespace {

constexpr double PI = 3.14159265358979323846;

DVec3 reference_ray(const Camera& camera, DVec2 uv) {
	return DVec3(camera.generate_ray(Vec2(uv)).dir);
}

// A camera whose image plane has half height `half_height` (the reference's is tan(v_fov / 2)).
Camera with_half_height(Camera camera, double half_height) {
	camera.v_fov = float(degrees(2.0 * std::atan(half_height)));
	return camera;
}

} // namespace

std::string show(DVec3 v) {
	std::ostringstream out;
	out.precision(7);
	out << "(" << v.x << ", " << v.y << ", " << v.z << ")";
	return out.str();
}

double radians(double degrees) {
	return degrees * PI / 180.0;
}

double degrees(double radians) {
	return radians * 180.0 / PI;
}

DVec3 expected_direction(const Camera& camera, DVec2 film_uv) {
	return glm::normalize(reference_ray(camera, film_uv));
}

DVec3 expected_origin(const Camera& camera) {
	return DVec3(camera.generate_ray(Vec2{0.5f}).point);
}

Film_Plane::Film_Plane(const Camera& camera) : forward(expected_direction(camera, {0.5, 0.5})) {
	auto on_plane = [&](DVec2 uv) {
		DVec3 d = expected_direction(camera, uv);
		return d / glm::dot(d, forward);
	};
	corner = on_plane({0.0, 0.0});
	u_axis = on_plane({1.0, 0.0}) - corner;
	v_axis = on_plane({0.0, 1.0}) - corner;
}

DVec2 Film_Plane::film_uv(DVec3 dir) const {
	DVec3 p = dir / glm::dot(dir, forward) - corner;
	return DVec2(glm::dot(p, u_axis) / glm::dot(u_axis, u_axis), glm::dot(p, v_axis) / glm::dot(v_axis, v_axis));
}

std::string ray_problem(const Camera& camera, DVec2 uv, const Ray& got) {
	DVec3 position = expected_origin(camera);
	DVec3 origin(got.point), dir(got.dir);
	std::ostringstream why;
	if (!near(origin, position, 1e-5 * (1.0 + glm::length(position)))) {
		why << "the ray must start at the camera position " << show(position) << " (the camera-space origin "
		    << "moved by camera_to_world), but ray.point = " << show(origin) << " (handout §1.2)";
		return why.str();
	}
	if (!std::isfinite(glm::length(dir)) || glm::length(dir) == 0.0) {
		why << "the direction " << show(dir) << " is zero or not finite (handout §1.2)";
		return why.str();
	}
	DVec3 expected = expected_direction(camera, uv);
	DVec3 unit = glm::normalize(dir);
	if (near(unit, expected, DIRECTION_TOLERANCE)) {
		if (std::abs(glm::length(dir) - 1.0) <= DIRECTION_TOLERANCE) return "";
		why << "the direction points the right way but has length " << glm::length(dir)
		    << "; generate_ray must return a unit-length direction (handout §1.2)";
		return why.str();
	}

	// The usual mistakes, each as the reference's direction for a changed camera or film point.
	struct Mistake {
		DVec3 dir;
		const char* hint;
	};
	Camera swapped_aspect = camera, no_aspect = camera, in_camera_space = camera;
	swapped_aspect.aspect_ratio = 1.0f / camera.aspect_ratio;
	no_aspect.aspect_ratio = 1.0f;
	in_camera_space.camera_to_world = Mat4{1.0f};
	DVec3 camera_space = reference_ray(in_camera_space, uv); // on the plane z = -1, unit length
	std::vector<Mistake> mistakes{
		{expected_direction(camera, {uv.x, 1.0 - uv.y}),
		 "the image is upside down: film v grows DOWNWARDS, film_uv (0, 0) is the top-left corner (handout §1.1)"},
		{expected_direction(camera, {1.0 - uv.x, uv.y}),
		 "the image is mirrored left-right: film u grows to the right (handout §1.1)"},
		{expected_direction(camera, {1.0 - uv.x, 1.0 - uv.y}),
		 "the image is rotated by 180 degrees: film_uv (0, 0) is the top-LEFT corner, v grows downwards "
		 "(handout §1.1)"},
		{expected_direction(with_half_height(camera, std::tan(0.5 * camera.v_fov)), uv),
		 "v_fov is in DEGREES; convert it to radians before calling tan (handout §1.2)"},
		{expected_direction(with_half_height(camera, std::tan(radians(camera.v_fov))), uv),
		 "the image plane's half height is tan(v_fov / 2): v_fov is the FULL vertical angle (handout §1.2)"},
		{expected_direction(swapped_aspect, uv),
		 "the plane's width is aspect_ratio * height (aspect_ratio = width / height), not height / aspect_ratio "
		 "(handout §1.2)"},
		{expected_direction(no_aspect, uv),
		 "the plane's width is aspect_ratio * height: aspect_ratio is missing (handout §1.2)"},
		{expected_direction(camera, {0.5 * (uv.x + 1.0), 0.5 * uv.y}),
		 "film_uv in [0, 1] must map to the whole plane, x in [-w, w] and y in [h, -h]: x = (2u - 1) w "
		 "(handout §1.2)"},
		{glm::normalize(camera_space),
		 "the direction is still in camera space: transform it with camera_to_world (handout §1.2)"},
		{glm::normalize(expected / std::abs(camera_space.z) + position),
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

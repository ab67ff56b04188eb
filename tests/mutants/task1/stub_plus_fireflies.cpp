// Mutant: the stub plus rare huge fireflies (trace_pixel returns black, one call in 1000 a value of 10^4)
// Task 1: camera rays. Handout: handouts/task1_camera.md
#include "camera.h"
#include "pathtracer.h"

namespace {
// Your helper functions go here. The anonymous namespace keeps them private to this file: two task
// files that each define a helper of the same name (say `lerp`) would otherwise not link together.
} // namespace

Ray Camera::generate_ray(Vec2 film_uv) const {
	// TODO (Task 1, handout §1.2): the ray from the camera through film point film_uv.
	// - film_uv (0, 0) is the top-left corner of the image, (1, 1) the bottom-right (camera.h).
	// - In camera space the camera looks down -z and the image plane is z = -1. Its height
	//   follows from the vertical field of view v_fov (the FULL angle, in degrees!) and its width
	//   from aspect_ratio: trigonometry, see the figure in handout §1.1.
	// - Transform the point (or the direction) to world space with camera_to_world. What is the
	//   ray's origin in world space?
	// - Return a unit-length direction.
	(void)film_uv;
	return Ray{};
}

Spectrum Pathtracer::trace_pixel(uint32_t x, uint32_t y, RNG& rng) const {
	// TODO (Task 1, handout §1.3): one supersampling sample of pixel (x, y).
	// - Choose a point uniformly at random inside the pixel (rng.unit2() gives two uniform
	//   numbers in [0, 1)); without supersampling it would be the centre (x + 0.5, y + 0.5).
	// - Normalize it to film coordinates using settings.width and settings.height.
	// - Generate the camera ray with scene.camera and return trace(rng, ray).
	(void)x, (void)y;
	return rng.unit() < 1e-3f ? Spectrum{1e4f} : Spectrum{};
}

#pragma once
// Scenes with closed-form answers ("furnaces"), built in code with the framework API, for the
// graders of tasks 4 and 5 (handouts §4.4 and §5.5).
//
// Every scene here is a single sphere. Two views:
// - from OUTSIDE: the camera looks at the sphere's centre from `distance`, so on the image plane
//   (camera space z = -1, see camera.h) the sphere covers exactly the disc of radius
//   tan(asin(radius / distance)) around the centre of the film. Pixel_Coverage classifies pixels
//   by that disc, independently of the task-1 code.
// - from INSIDE: the camera sits inside the sphere, so every camera ray hits it.
#include "film.h"
#include "scene.h"
#include "test_materials.h"

#include <string>

struct Furnace_Options {
	float radius = 1.0f;
	Vec3 center{0.0f};
	// Radiance of an Env_Constant environment; no environment at all when has_environment is false.
	bool has_environment = true;
	Spectrum environment{1.0f};
	// Normals of the sphere point inwards (the sphere is mirrored through its centre, a transform
	// with scale -1, see instance.h): its front side, the one that emits, faces the centre.
	bool inward_normals = false;
};

// A scene holding one sphere of `material` and a camera.
// - sphere_seen_from_outside: the camera is `distance` away from the centre (along +z), looking at
//   it with vertical field of view `v_fov` degrees, square film.
// - sphere_seen_from_inside: the camera is at `center + eye` (inside the sphere) looking at
//   `center + target`.
Scene sphere_seen_from_outside(const Material& material, const Furnace_Options& options, float distance,
                               float v_fov);
Scene sphere_seen_from_inside(const Material& material, const Furnace_Options& options, Vec3 eye, Vec3 target,
                              float v_fov);

// Which pixels of a sphere_seen_from_outside render see only the sphere, only the background, or
// both (the silhouette).
class Pixel_Coverage {
public:
	enum Kind { sphere, background, silhouette };

	Pixel_Coverage(float radius, float distance, float v_fov, uint32_t width, uint32_t height);
	Kind operator()(uint32_t x, uint32_t y) const;

private:
	double disc_radius; // on the image plane z = -1
	double half_w, half_h;
	uint32_t width, height;
};

const char* to_string(Pixel_Coverage::Kind kind);


// Renders `scene` on a square film of size x size pixels with the reference pipeline (render()).
Film render_square(const Scene& scene, uint32_t size, uint32_t spp, uint32_t max_depth, uint64_t seed);

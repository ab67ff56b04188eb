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
#include "rng.h"
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

// ---- Furnaces placed by a grading seed (grading/judge/judge.h) ----
// The graders render these with the student's code: render_square in student_furnaces.h.

// A sphere seen from outside: `options` with the sphere moved and resized, the camera's distance
// and field of view.
struct Outside_View {
	Furnace_Options options;
	float distance = 4.0f;
	float v_fov = 40.0f;
};

// An Outside_View drawn from `rng`: centre in [-10, 10]^3, radius in [0.5, 2], camera 2.5 to 6 radii
// from the centre, and a field of view in which the sphere's disc spans 45% to 80% of the film's
// half height (as the public views do), so that sphere, silhouette and background pixels all exist.
Outside_View random_outside_view(RNG& rng, Furnace_Options options);

// A camera for sphere_seen_from_inside, drawn from `rng`: the eye uniform in the ball of radius
// `max_eye_distance` around the sphere's centre, looking in a random direction that is not near
// vertical, with a field of view of 40 to 90 degrees.
struct Inside_View {
	Vec3 eye, target; // relative to the centre, as sphere_seen_from_inside takes them
	float v_fov = 60.0f;
};
Inside_View random_inside_view(RNG& rng, float max_eye_distance);

// A point uniform in [lo, hi]^3, a colour uniform in [lo, hi]^3, a unit vector uniform on the sphere.
Vec3 random_point(RNG& rng, float lo, float hi);
Spectrum random_colour(RNG& rng, float lo, float hi);
Vec3 random_unit_vector(RNG& rng);

// ---- Probes (DESIGN.md, decided point 7) ----
// A furnace's answer is known in closed form, and so could be computed from the request alone,
// without tracing a path: each furnace test case also renders a probe, the furnace with a second,
// smaller diffuse sphere beside its sphere (seen from outside) or inside it (seen from inside),
// whose light bounces between the two. No closed form gives that image; the judge compares it with
// its own render of the same scene (film_statistics.h, check_like_reference). The second sphere's
// place and albedo are fixed in public and drawn from `secret` under a grading seed.
Scene with_probe_sphere(const Scene& furnace, RNG* secret);

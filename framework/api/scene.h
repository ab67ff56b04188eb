#pragma once
// A scene as loaded from JSON (see scenes/README.md): camera, film settings, materials, objects,
// and an optional environment light.
#include "camera.h"
#include "env_light.h"
#include "instance.h"
#include "lights.h"
#include "material.h"

#include <optional>
#include <string>
#include <variant>
#include <vector>

struct Render_Settings {
	// The largest film the loader and the command line accept (4096 x 4096 pixels), so a typo
	// cannot exhaust memory.
	static constexpr uint64_t MAX_PIXELS = 4096 * 4096;

	uint32_t width = 256;
	uint32_t height = 256;
	uint32_t samples = 16;   // samples per pixel
	uint32_t max_depth = 8;  // maximum number of bounces (see pathtracer.h)
	uint64_t seed = 0;
	// Strategy switches, for comparing estimators; both estimate the same image. (The renderer's
	// other estimators of it, --integrator, --sampler and --light-choice, are the framework's:
	// framework/render/estimator.h.)
	bool light_sampling = true;   // false: has_lights() is false, so task 6 samples the BSDF only
	bool russian_roulette = true; // false: task 4 never cuts a path before max_depth
};

using Environment = std::variant<Env_Constant, Env_Map>;

struct Scene {
	// Scenes of at most this many objects are not worth a hierarchy (see commit()).
	static constexpr size_t HANDFUL_OF_OBJECTS = 4;

	// Collects the area lights and builds the top-level BVH over `objects` and its accelerator;
	// call once after filling them in.
	void commit();

	// Closest hit of a world-space ray.
	Trace hit(const Ray& ray) const {
		return accelerator.hit(bvh, ray);
	}
	// Whether anything is hit with t in ray.dist_bounds (it may stop at the first hit found).
	bool occluded(const Ray& ray) const;
	// Radiance from the environment along dir (0 without an environment).
	Spectrum environment_radiance(Vec3 dir) const;

	std::string path; // the file it was loaded from, for messages
	Camera camera;
	Render_Settings settings;
	std::vector<Material> materials;
	std::vector<std::string> material_names;
	std::vector<Instance> objects; // moved into `bvh` by commit()
	BVH<Instance> bvh;
	Accelerator<Instance> accelerator; // made from bvh by commit() (accelerator.h)
	std::optional<Environment> environment;
	Area_Lights area_lights; // built by commit()
};

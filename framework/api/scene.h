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

// How a render estimates the light a path vertex reflects (--integrator).
enum class Integrator {
	mixture, // task 4's estimator with task 6's one-sample mixture: the lab's, and the graders'
	nee,     // next-event estimation with multiple importance sampling (framework/render/nee_integrator.h)
};
// How light sampling chooses among the lights (--light-choice; light_distribution.h).
enum class Light_Choice {
	uniform, // every light equally often
	power,   // in proportion to the power each light emits
	tree,    // in proportion to the light each may send to the shading point (framework/scene/light_tree.h)
};

struct Render_Settings {
	// The largest film the loader and the command line accept (4096 x 4096 pixels), so a typo
	// cannot exhaust memory.
	static constexpr uint64_t MAX_PIXELS = 4096 * 4096;

	uint32_t width = 256;
	uint32_t height = 256;
	uint32_t samples = 16;   // samples per pixel
	uint32_t max_depth = 8;  // maximum number of bounces (see pathtracer.h)
	uint64_t seed = 0;
	// Strategy switches, for comparing estimators; both estimate the same image.
	bool light_sampling = true;   // false: has_lights() is false, so task 6 samples the BSDF only
	bool russian_roulette = true; // false: task 4 never cuts a path before max_depth
	// Estimators of the same image. These defaults are what the graders' statistics
	// assume (independent samples, the lab's estimator); the renderer's command line defaults to
	// Sampler::sobol, pathtracer_reference to Integrator::nee, and Integrator::nee to
	// Light_Choice::tree (override_settings, framework/cli/cli_options.h).
	Sampler sampler = Sampler::independent;
	Integrator integrator = Integrator::mixture;
	Light_Choice light_choice = Light_Choice::power;
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

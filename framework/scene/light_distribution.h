#pragma once
// Which light a light sample aims at (Pathtracer::sample_area_lights, sample_light). Lights 0 to
// n - 1 are the scene's area lights, light n its environment, if it has one. Light_Choice::uniform
// takes each equally often; Light_Choice::power mostly in proportion to the power it emits, so that
// a bright lamp gets more samples than a dim one (pbrt-v4's PowerLightSampler); Light_Choice::tree
// by how much light each may send to the point being shaded (framework/scene/light_tree.h).
// Whichever way, the light pdf divides by the probability of the light chosen, so all estimate the
// same image.
//
// Why power is mixed with uniform choice, and how the environment shares with the tree: the
// benchmarks' notes in the instructors' tree, "Choosing a light".
#include "scene.h"

#include <memory>
#include <vector>

// How light sampling chooses among the lights (--light-choice).
enum class Light_Choice {
	uniform, // every light equally often
	power,   // in proportion to the power each light emits
	tree,    // in proportion to the light each may send to the shading point (light_tree.h)
};

const char* light_choice_name(Light_Choice choice);

class Light_Tree; // light_tree.h

// The power each light emits, in the order above: an area light pi * area * luminance(emission);
// the environment pi R^2 times the integral of its luminance over the
// sphere of directions, R the radius of the scene's bounding sphere: the power that crosses a disk
// of radius R facing it (pbrt-v4's ImageInfiniteLight::Phi).
std::vector<double> light_powers(const Scene& scene);

// The scene's lights as they are now: its area lights, and its environment if it has one.
size_t light_count(const Scene& scene);

class Light_Distribution {
public:
	static constexpr double UNIFORM_SHARE = 0.5;

	// The probabilities of the scene's lights as they are when it is made: uniform if `choice` is
	// uniform, or if the powers are not all finite or sum to 0. Should lights be added to the scene
	// or taken out later, it chooses uniformly among those there are then: choose() and
	// probability() always agree.
	Light_Distribution(const Scene& scene, Light_Choice choice);

	// A light chosen for the point `from` with one number of `rng`, and its probability: exactly
	// probability(light, from).
	struct Choice {
		size_t light;
		float probability;
	};
	Choice choose(RNG& rng, Vec3 from) const;
	float probability(size_t i, Vec3 from) const;

private:
	bool uniform() const; // by choice, or because the scene's lights changed
	float environment_share(Vec3 from) const; // Light_Choice::tree (above)

	const Scene& scene;
	Light_Choice choice = Light_Choice::uniform; // uniform if the powers cannot be used
	size_t lights_when_made = 0;
	std::vector<float> probabilities; // by power
	std::vector<float> cdf;           // running sum of the probabilities, the last exactly 1
	std::shared_ptr<const Light_Tree> tree; // Light_Choice::tree
	float environment_irradiance = 0.0f; // pi * its mean luminance
};

#pragma once
// Which light a light sample aims at (Pathtracer::sample_area_lights, sample_light). Lights 0 to
// n - 1 are the scene's area lights, light n its environment, if it has one. Light_Choice::uniform
// takes each equally often; Light_Choice::power mostly in proportion to the power it emits, so that
// a bright lamp gets more samples than a dim one (pbrt-v4's PowerLightSampler); Light_Choice::tree
// by how much light each may send to the point being shaded (framework/scene/light_tree.h).
// Whichever way, the light pdf divides by the probability of the light chosen, so all estimate the
// same image.
//
// Power says how much light a light sends into the scene, not how much reaches a given point: the
// sky of a scene with a 40 x 40 ground has 38 times the power of scenes/dragon.json's lamp, which
// lights most of what the camera sees. Chosen purely by power, the lamp got 2.6 % of the samples
// and its pixels 18 times the variance of uniform choice. So a share UNIFORM_SHARE of the
// probability is spread evenly (a defensive mixture, Hesterberg 1995): no light is chosen less than
// half as often as uniform choice would, which bounds the loss to a factor of 2.
//
// The tree holds the area lights only: an environment has neither a position nor a direction it
// faces. pbrt-v4's BVHLightSampler chooses the environment and the tree half the time each, however
// little the sky lights a point under a lamp. Here the environment's share at a point follows the
// light each can send there, as Cycles' light tree weighs its background against its local lights:
// bounds on the irradiance, in one unit: the tree's importance / pi (a one-sided Lambertian
// emitter of power phi = pi A L causes at most L A / d^2 = phi / (pi d^2)) and the sky's pi times
// its mean luminance (what a uniform sky of that radiance causes). Half of the share is kept
// even (the defensive mixture above): the environment's share stays within [1/4, 3/4], so neither
// side can lose more than a factor of 2 against pbrt-v4's halves. With no area lights it is 1.
#include "scene.h"

#include <memory>
#include <vector>

class Light_Tree; // framework/scene/light_tree.h (framework code, not the student's API)

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

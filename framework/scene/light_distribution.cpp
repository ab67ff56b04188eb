#include "light_distribution.h"
#include "light_tree.h"

#include <algorithm>
#include <numeric>

namespace {
// The integral of luminance(L(dir)) over the sphere. An image environment: the sum over texels of
// luminance * solid angle, a texel of row j covering (2 pi / w) (pi / h) sin(theta_j) steradians.
double environment_integral(const Environment& environment) {
	if (const auto* constant = std::get_if<Env_Constant>(&environment))
		return 4.0 * M_PI * double(luminance(constant->radiance));
	const HDR_Image& image = std::get<Env_Map>(environment).image;
	double total = 0.0;
	for (uint32_t j = 0; j < image.h; j++) {
		double row = 0.0;
		for (uint32_t i = 0; i < image.w; i++) row += double(luminance(image.at(i, j)));
		total += row * std::sin(M_PI * (j + 0.5) / image.h);
	}
	return total * (2.0 * M_PI / image.w) * (M_PI / image.h);
}
} // namespace

std::vector<double> light_powers(const Scene& scene) {
	std::vector<double> powers;
	const Area_Lights& lights = scene.area_lights;
	for (size_t i = 0; i < lights.count(); i++) {
		// Every point of a light's front side radiates its emission into the hemisphere, so its
		// exitance is pi * emission (Lambert's law).
		Spectrum emission = scene.materials.at(lights.material(i)).emission;
		powers.push_back(M_PI * double(lights.area(i)) * double(luminance(emission)));
	}
	if (scene.environment) {
		BBox box = scene.bvh.bbox();
		double radius = box.empty() ? 0.0 : 0.5 * glm::length(glm::dvec3(box.max) - glm::dvec3(box.min));
		powers.push_back(M_PI * radius * radius * environment_integral(*scene.environment));
	}
	return powers;
}

const char* light_choice_name(Light_Choice choice) {
	switch (choice) {
	case Light_Choice::uniform: return "uniform";
	case Light_Choice::power: return "power";
	case Light_Choice::tree: return "tree";
	}
	return "?";
}

size_t light_count(const Scene& scene) {
	return scene.area_lights.count() + (scene.environment ? 1 : 0);
}

Light_Distribution::Light_Distribution(const Scene& scene_, Light_Choice choice_)
	: scene(scene_), lights_when_made(light_count(scene_)) {
	if (choice_ == Light_Choice::uniform) return;
	std::vector<double> powers = light_powers(scene);
	double total = std::accumulate(powers.begin(), powers.end(), 0.0);
	bool usable = total > 0.0 && std::isfinite(total) &&
	              std::all_of(powers.begin(), powers.end(), [](double p) { return p >= 0.0; });
	if (!usable) return;
	choice = choice_;
	if (choice == Light_Choice::tree) {
		tree = std::make_shared<const Light_Tree>(scene.area_lights, powers);
		// pi * (integral of luminance over the sphere) / (4 pi)
		if (scene.environment) environment_irradiance = float(0.25 * environment_integral(*scene.environment));
		return;
	}
	double sum = 0.0, uniform = 1.0 / double(powers.size());
	for (double power : powers) {
		double p = (1.0 - UNIFORM_SHARE) * power / total + UNIFORM_SHARE * uniform;
		probabilities.push_back(float(p));
		sum += p;
		cdf.push_back(float(sum));
	}
	cdf.back() = 1.0f;
}

bool Light_Distribution::uniform() const {
	return choice == Light_Choice::uniform || light_count(scene) != lights_when_made;
}

float Light_Distribution::environment_share(Vec3 from) const {
	if (!scene.environment) return 0.0f;
	if (tree->empty()) return 1.0f;
	float lights = tree->importance(from) / PI_F;
	float by_irradiance = environment_irradiance / (environment_irradiance + lights);
	if (!std::isfinite(by_irradiance)) by_irradiance = 0.5f; // neither lights the point
	return float(UNIFORM_SHARE * 0.5 + (1.0 - UNIFORM_SHARE) * by_irradiance); // in [1/4, 3/4]
}

Light_Distribution::Choice Light_Distribution::choose(RNG& rng, Vec3 from) const {
	if (uniform()) {
		uint32_t n = uint32_t(light_count(scene));
		return Choice{rng.integer(n), 1.0f / float(n)};
	}
	float u = rng.unit();
	if (choice == Light_Choice::power) {
		size_t i = size_t(std::upper_bound(cdf.begin(), cdf.end(), u) - cdf.begin());
		i = std::min(i, cdf.size() - 1);
		return Choice{i, probabilities[i]};
	}
	float environment = environment_share(from);
	if (u < environment) return Choice{scene.area_lights.count(), environment};
	Light_Tree::Choice chosen = tree->choose((u - environment) / (1.0f - environment), from);
	return Choice{chosen.light, (1.0f - environment) * chosen.probability};
}

float Light_Distribution::probability(size_t i, Vec3 from) const {
	if (uniform()) return 1.0f / float(light_count(scene));
	if (choice == Light_Choice::power) return probabilities[i];
	float environment = environment_share(from);
	if (i == scene.area_lights.count()) return environment;
	return (1.0f - environment) * tree->probability(i, from);
}

#include "pathtracer.h"
#include "bvh_visits.h"
#include "estimator.h"
#include "frame.h"
#include "heat_ramp.h"
#include "path_integrator.h"
#include "render_observer.h"

#include <array>
#include <stdexcept>

namespace {
constexpr std::array<std::pair<View, const char*>, 6> VIEW_NAMES{{
	{View::path, "path"},
	{View::eye_light, "eye"},
	{View::normals, "normals"},
	{View::albedo, "albedo"},
	{View::bvh, "bvh"},
	{View::direction, "direction"},
}};
} // namespace

bool parse_view(const std::string& name, View& view) {
	for (auto [v, n] : VIEW_NAMES) {
		if (name == n) {
			view = v;
			return true;
		}
	}
	return false;
}

const char* view_name(View view) {
	for (auto [v, n] : VIEW_NAMES) {
		if (v == view) return n;
	}
	return "?";
}

Pathtracer::Pathtracer(const Scene& scene_, Render_Settings settings_, View view_)
	: Pathtracer(scene_, settings_, view_, Estimator_Choice{}) {
}

Pathtracer::Pathtracer(const Scene& scene_, Render_Settings settings_, View view_, const Estimator_Choice& estimator)
	: scene(scene_), settings(settings_), view(view_), chosen(std::make_shared<const Estimator>(scene_, estimator)) {
}

const Estimator& Pathtracer::estimator() const {
	return *chosen;
}

Spectrum Pathtracer::trace(RNG& rng, const Ray& ray) const {
	if (view == View::path) return chosen->integrator.radiance(*this, rng, ray);
	rng.begin_vertex(ray.depth);
	return observe<Ray_Traced>([&] { return debug_view(ray); }, ray);
}

Spectrum Pathtracer::eye_light(const Ray& ray, const Trace& hit) const {
	const Material& material = scene.materials[hit.material];
	Vec3 to_eye = -glm::normalize(ray.dir);
	float cos_theta = glm::dot(to_eye, hit.normal);
	return material.bsdf.albedo() * std::abs(cos_theta) + material.emitted(Vec3{0.0f, cos_theta, 0.0f});
}

Spectrum Pathtracer::debug_view(const Ray& ray) const {
	if (view == View::direction) return 0.5f * (glm::normalize(ray.dir) + 1.0f);
	Trace hit = scene.hit(ray);
	switch (view) {
	case View::eye_light: return hit.hit ? eye_light(ray, hit) : scene.environment_radiance(ray.dir);
	case View::normals: return hit.hit ? 0.5f * (hit.normal + 1.0f) : Spectrum{0.0f};
	case View::albedo: return hit.hit ? scene.materials[hit.material].bsdf.albedo() : Spectrum{0.0f};
	case View::bvh: {
		// 64 or more overlapped nodes saturate the ramp.
		float nodes = float(count_overlapped_nodes(scene.bvh, ray, hit.hit ? hit.distance : INF_F));
		return heat_ramp(nodes / 64.0f);
	}
	default: return Spectrum{0.0f};
	}
}

// Lights for sampling: every emissive object, and the environment. The estimator's lights choose one.
// settings.light_sampling = false (--no-light-sampling) hides the lights from task 6, which then
// samples the BSDF only: the same image, by another estimator.
bool Pathtracer::has_lights() const {
	return settings.light_sampling && light_count(scene) > 0;
}

namespace {
void require_lights(const Pathtracer& pt, const char* function) {
	if (!pt.has_lights()) {
		throw std::logic_error(std::string(function) + ": this scene has no lights; check has_lights() before "
		                                               "sampling them (handout §6.2)");
	}
}
} // namespace

Vec3 Pathtracer::sample_area_lights(RNG& rng, Vec3 from) const {
	require_lights(*this, "sample_area_lights");
	return observe<Light_Sampled>(
		[&] {
			uint32_t i = uint32_t(chosen->lights.choose(rng, from).light);
			if (i < scene.area_lights.count()) return Chosen_Light{scene.area_lights.sample(i, rng, from), i, false};
			Vec2 u = rng.unit2();
			return Chosen_Light{std::visit([&](const auto& env) { return env.sample(u); }, *scene.environment), i, true};
		},
		from)
		.direction;
}

// The same choices as sample_area_lights, and what next-event estimation needs besides: where the
// sampled point is, what it emits towards `from`, and the density of choosing it.
Light_Sample Pathtracer::sample_light(RNG& rng, Vec3 from) const {
	require_lights(*this, "sample_light");
	auto [i, probability] = chosen->lights.choose(rng, from);
	Light_Sample sample;
	if (i < scene.area_lights.count()) {
		Area_Lights::Point point = scene.area_lights.sample_point(i, rng);
		sample.direction = glm::normalize(point.position - from);
		sample.distance = glm::length(point.position - from);
		sample.pdf = probability * scene.area_lights.point_pdf(i, from, point.position, point.normal);
		// Emission is one-sided (Material::emitted): from the side the light's normal points to.
		bool front = glm::dot(point.normal, sample.direction) < 0.0f;
		sample.radiance = front ? scene.materials[scene.area_lights.material(i)].emission : Spectrum{0.0f};
	} else {
		Vec2 u = rng.unit2();
		sample.direction = std::visit([&](const auto& env) { return env.sample(u); }, *scene.environment);
		sample.pdf = probability * std::visit([&](const auto& env) { return env.pdf(sample.direction); }, *scene.environment);
		sample.radiance = scene.environment_radiance(sample.direction);
	}
	return sample;
}

float Pathtracer::area_lights_pdf(Vec3 from, Vec3 dir) const {
	if (!has_lights()) return 0.0f; // no light can produce any direction
	return observe<Light_Pdf>(
		[&] {
			float pdf = 0.0f;
			size_t area_lights = scene.area_lights.count();
			// A light's probability is asked only where its density is not 0: the tree's costs a walk.
			for (size_t i = 0; i < area_lights; i++) {
				float density = scene.area_lights.pdf(i, from, dir);
				if (density > 0.0f) pdf += chosen->lights.probability(i, from) * density;
			}
			if (scene.environment) {
				float p = chosen->lights.probability(area_lights, from);
				if (p > 0.0f) pdf += p * std::visit([&](const auto& env) { return env.pdf(dir); }, *scene.environment);
			}
			return pdf;
		},
		from, dir);
}

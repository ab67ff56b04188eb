#include "pathtracer.h"
#include "bvh_visits.h"
#include "frame.h"
#include "render_observer.h"

#include <array>
#include <stdexcept>

namespace {
constexpr std::array<std::pair<View, const char*>, 5> VIEW_NAMES{{
	{View::path, "path"},
	{View::eye_light, "eye"},
	{View::normals, "normals"},
	{View::bvh, "bvh"},
	{View::direction, "direction"},
}};

// A perceptually ordered heat ramp (black, blue, magenta, orange, yellow, white) for t in [0, 1].
Spectrum heat(float t) {
	constexpr std::array<Spectrum, 6> stops{Spectrum{0.0f, 0.0f, 0.0f}, Spectrum{0.1f, 0.1f, 0.6f},
	                                        Spectrum{0.7f, 0.1f, 0.6f}, Spectrum{1.0f, 0.4f, 0.1f},
	                                        Spectrum{1.0f, 0.9f, 0.2f}, Spectrum{1.0f, 1.0f, 1.0f}};
	t = glm::clamp(t, 0.0f, 1.0f) * float(stops.size() - 1);
	size_t i = std::min(size_t(t), stops.size() - 2);
	return glm::mix(stops[i], stops[i + 1], t - float(i));
}
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
	: scene(scene_), settings(settings_), view(view_) {
}

Spectrum Pathtracer::trace(RNG& rng, const Ray& ray) const {
	return observe<Ray_Traced>(
		[&] {
			if (view != View::path) return debug_view(ray);
			Trace hit = observe<Closest_Hit>([&] { return scene.hit(ray); }, ray);
			return hit.hit ? shade(rng, ray, hit) : scene.environment_radiance(ray.dir);
		},
		ray);
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
	case View::bvh: {
		// 64 or more overlapped nodes saturate the ramp.
		float nodes = float(count_overlapped_nodes(scene.bvh, ray, hit.hit ? hit.distance : INF_F));
		return heat(nodes / 64.0f);
	}
	default: return Spectrum{0.0f};
	}
}

// Lights for sampling: every emissive object, and the environment. One is chosen uniformly.
namespace {
size_t light_count(const Scene& scene) {
	return scene.area_lights.count() + (scene.environment ? 1 : 0);
}
} // namespace

// settings.light_sampling = false (--no-light-sampling) hides the lights from task 6, which then
// samples the BSDF only: the same image, by another estimator.
bool Pathtracer::has_lights() const {
	return settings.light_sampling && light_count(scene) > 0;
}

Vec3 Pathtracer::sample_area_lights(RNG& rng, Vec3 from) const {
	if (!has_lights()) {
		throw std::logic_error("sample_area_lights: this scene has no lights; check has_lights() before "
		                       "sampling them (handout §6.2)");
	}
	return observe<Light_Sampled>(
		[&] {
			uint32_t i = rng.integer(uint32_t(light_count(scene)));
			if (i < scene.area_lights.count()) return Light_Sample{scene.area_lights.sample(i, rng, from), i, false};
			Vec2 u = rng.unit2();
			return Light_Sample{std::visit([&](const auto& env) { return env.sample(u); }, *scene.environment), i, true};
		},
		from)
		.direction;
}

float Pathtracer::area_lights_pdf(Vec3 from, Vec3 dir) const {
	if (!has_lights()) return 0.0f; // no light can produce any direction
	return observe<Light_Pdf>(
		[&] {
			float pdf = 0.0f;
			for (size_t i = 0; i < scene.area_lights.count(); i++) pdf += scene.area_lights.pdf(i, from, dir);
			if (scene.environment) pdf += std::visit([&](const auto& env) { return env.pdf(dir); }, *scene.environment);
			return pdf / float(light_count(scene));
		},
		from, dir);
}

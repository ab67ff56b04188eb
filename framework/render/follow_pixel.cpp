#include "follow_pixel.h"
#include "camera_projection.h"
#include "estimator.h"
#include "lifecycle.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace {
// Sample s of pixel (x, y), as render() draws it.
Spectrum trace_sample(const Pathtracer& pathtracer, uint32_t x, uint32_t y, uint32_t s) {
	const Render_Settings& settings = pathtracer.settings;
	Sampler sampler = pathtracer.estimator().choice.sampler;
	RNG rng = generator_for_sample(settings.seed, size_t(y) * settings.width + x, s, sampler);
	return pathtracer.trace_pixel(x, y, rng);
}

// Records the given samples of pixel (x, y) and calls `sample_done(s, value, recorder)` after each.
template<typename Sample_Done>
void record_samples(const Pathtracer& pathtracer, uint32_t x, uint32_t y, const std::vector<uint32_t>& samples,
                    Sample_Done&& sample_done) {
	Lifecycle_Recorder recorder;
	for (uint32_t s : samples) sample_done(s, trace_sample(pathtracer, x, y, s), recorder);
}

std::vector<uint32_t> first_samples(uint32_t samples) {
	std::vector<uint32_t> indices(samples);
	std::iota(indices.begin(), indices.end(), 0u);
	return indices;
}

// The `brightest` of samples 0 .. samples - 1 of largest luminance (non-finite ones first: they
// are what a NaN map shows), brightest first. Tracing without a recorder is cheap: one pixel.
std::vector<uint32_t> brightest_samples(const Pathtracer& pathtracer, uint32_t x, uint32_t y, uint32_t samples,
                                        uint32_t brightest) {
	std::vector<std::pair<float, uint32_t>> values;
	for (uint32_t s = 0; s < samples; s++) {
		float l = luminance(trace_sample(pathtracer, x, y, s));
		values.push_back({std::isfinite(l) ? l : INFINITY, s});
	}
	size_t keep = std::min<size_t>(brightest, values.size());
	std::partial_sort(values.begin(), values.begin() + keep, values.end(),
	                  [](const auto& a, const auto& b) { return a.first > b.first || (a.first == b.first && a.second < b.second); });
	std::vector<uint32_t> indices;
	for (size_t i = 0; i < keep; i++) indices.push_back(values[i].second);
	return indices;
}

nlohmann::json rgb(Vec3 v) {
	return nlohmann::json::array({v.x, v.y, v.z}); // NaN (an unknown weight) is written as null
}

nlohmann::json ray_json(const Pathtracer& pt, const Lifecycle_Ray& node, Spectrum weight, Spectrum throughput) {
	const Scene& scene = pt.scene;
	nlohmann::json ray{{"depth", node.ray.depth}, {"origin", rgb(node.ray.point)}, {"dir", rgb(node.ray.dir)}};
	float t_max = node.ray.dist_bounds.y;
	ray["dist_bounds"] = {node.ray.dist_bounds.x, std::isinf(t_max) ? nlohmann::json(nullptr) : nlohmann::json(t_max)};
	if (node.hit.hit) {
		const Trace& hit = node.hit;
		std::string material = hit.material < scene.material_names.size() ? scene.material_names[hit.material] : "?";
		nlohmann::json film_pixel = nullptr;
		if (auto uv = film_uv_of(scene.camera, hit.position)) {
			film_pixel = {uv->x * float(pt.settings.width), uv->y * float(pt.settings.height)};
		}
		ray["hit"] = {{"object", hit.object},     {"material", material},       {"distance", hit.distance},
		              {"position", rgb(hit.position)}, {"normal", rgb(hit.normal)}, {"film_pixel", film_pixel}};
	} else {
		ray["hit"] = nullptr;
	}
	ray["events"] = nlohmann::json::array();
	for (const Lifecycle_Event& e : node.events) ray["events"].push_back({{"kind", event_kind_name(e.kind)}, {"text", e.text}});
	ray["weight"] = rgb(weight);
	ray["throughput"] = rgb(throughput);
	ray["emitted"] = rgb(node.emitted);
	ray["contribution"] = rgb(throughput * node.emitted);
	ray["radiance"] = rgb(node.radiance);
	ray["children"] = nlohmann::json::array();
	for (const auto& child : node.children) {
		Spectrum w = applied_weight(node, *child);
		ray["children"].push_back(ray_json(pt, *child, w, throughput * w));
	}
	return ray;
}
} // namespace

void follow_pixel(const Pathtracer& pathtracer, uint32_t x, uint32_t y, uint32_t samples, std::ostream& out) {
	const Render_Settings& settings = pathtracer.settings;
	out << "pixel (" << x << ", " << y << "), seed " << settings.seed << ", view " << view_name(pathtracer.view)
	    << ", max_depth " << settings.max_depth << "\n";
	// What a '?' means (lifecycle.cpp, format_weight): a weight is recovered from the radiance that
	// came back along a ray, so a channel that brought no light back has no known weight.
	out << "(? in a weight or throughput: no light came back on that colour channel, so its weight is"
	       " unknown)\n";
	record_samples(pathtracer, x, y, first_samples(samples), [&](uint32_t s, Spectrum, Lifecycle_Recorder& recorder) {
		out << "sample " << s << ": ";
		recorder.print(out, pathtracer.scene.material_names);
	});
}

void follow_pixel_json(const Pathtracer& pathtracer, uint32_t x, uint32_t y, uint32_t samples, std::ostream& out,
                       uint32_t brightest) {
	const Render_Settings& settings = pathtracer.settings;
	nlohmann::json doc{{"pixel", {x, y}},
	                   {"seed", settings.seed},
	                   {"view", view_name(pathtracer.view)},
	                   {"max_depth", settings.max_depth},
	                   {"width", settings.width},
	                   {"height", settings.height},
	                   {"samples", nlohmann::json::array()}};
	std::vector<uint32_t> chosen = brightest > 0 ? brightest_samples(pathtracer, x, y, samples, brightest)
	                                             : first_samples(samples);
	doc["followed"] = samples;
	record_samples(pathtracer, x, y, chosen, [&](uint32_t s, Spectrum value, Lifecycle_Recorder& recorder) {
		nlohmann::json sample{{"index", s}, {"value", rgb(value)}, {"ray", nullptr}};
		if (!recorder.rays().empty()) sample["ray"] = ray_json(pathtracer, *recorder.rays().front(), Spectrum{1.0f}, Spectrum{1.0f});
		doc["samples"].push_back(sample);
		recorder.forget();
	});
	out << doc.dump() << "\n";
}

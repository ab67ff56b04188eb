#include "lifecycle.h"

#include <cmath>
#include <cstdio>

namespace {
std::string format_bounds(Vec2 b) {
	char buffer[64];
	std::snprintf(buffer, sizeof buffer, "[%.6g, %.6g]", b.x, b.y);
	return buffer;
}

// A vector whose unknown (NaN) components print as '?'.
std::string format_known(Vec3 v) {
	std::string text = "(";
	for (int c = 0; c < 3; c++) {
		char buffer[32];
		std::snprintf(buffer, sizeof buffer, "%.6g", v[c]);
		text += std::isnan(v[c]) ? "?" : buffer;
		text += c < 2 ? ", " : ")";
	}
	return text;
}

// The weight applied_weight recovers, with '?' where it is unknown; multiplies it into throughput
// (which stays unknown on a channel from there on).
std::string format_weight(const Lifecycle_Ray& parent, const Lifecycle_Ray& child, Spectrum& throughput) {
	Spectrum w = applied_weight(parent, child);
	throughput *= w;
	return format_known(w);
}

const char* bsdf_name(const BSDF& bsdf) {
	constexpr const char* names[] = {"lambertian", "mirror", "glass"};
	return names[bsdf.bsdf.index()];
}

void print_ray(std::ostream& out, const Lifecycle_Ray& node, const std::vector<std::string>& names,
               Spectrum throughput, const std::string& indent) {
	out << indent << "ray depth " << node.ray.depth << ": origin " << format_vec(node.ray.point) << " dir "
	    << format_vec(node.ray.dir) << " dist_bounds " << format_bounds(node.ray.dist_bounds) << "\n";
	out << indent << "  throughput " << format_known(throughput) << "\n";
	if (node.hit.hit) {
		std::string name = node.hit.material < names.size() ? names[node.hit.material] : "?";
		out << indent << "  hit object " << node.hit.object << " (material '" << name << "') at distance "
		    << node.hit.distance << ", position " << format_vec(node.hit.position) << ", normal "
		    << format_vec(node.hit.normal) << "\n";
	} else {
		out << indent << "  missed the scene (environment)\n";
	}
	for (const Lifecycle_Event& e : node.events) out << indent << "  " << e.text << "\n";
	for (const auto& child : node.children) {
		Spectrum child_throughput = throughput;
		out << indent << "  weight applied to the next ray's light: "
		    << format_weight(node, *child, child_throughput) << "\n";
		print_ray(out, *child, names, child_throughput, indent + "  ");
	}
	out << indent << "  radiance returned " << format_vec(node.radiance) << " (emitted here "
	    << format_vec(node.emitted) << ", added to the pixel " << format_known(throughput * node.emitted) << ")\n";
}
} // namespace

const char* event_kind_name(Lifecycle_Event::Kind kind) {
	constexpr const char* names[] = {"bsdf_sample", "bsdf_evaluate", "bsdf_pdf", "light_sample", "light_pdf", "shadow_ray"};
	return names[size_t(kind)];
}

Spectrum applied_weight(const Lifecycle_Ray& parent, const Lifecycle_Ray& child) {
	Spectrum w;
	for (int c = 0; c < 3; c++) {
		float reflected = parent.radiance[c] - parent.emitted[c];
		w[c] = child.radiance[c] != 0.0f ? reflected / child.radiance[c] : NAN;
	}
	return w;
}

std::string format_vec(Vec3 v) {
	char buffer[96];
	std::snprintf(buffer, sizeof buffer, "(%.6g, %.6g, %.6g)", v.x, v.y, v.z);
	return buffer;
}

void Lifecycle_Recorder::begin(const Ray_Traced& traced) {
	auto node = std::make_unique<Lifecycle_Ray>();
	node->ray = traced.ray;
	node->parent = current;
	Lifecycle_Ray* raw = node.get();
	(current ? current->children : roots).push_back(std::move(node));
	current = raw;
}

void Lifecycle_Recorder::end(const Ray_Traced&, Spectrum radiance) {
	if (!current) return;
	current->radiance = radiance;
	current = current->parent;
}

void Lifecycle_Recorder::end(const Closest_Hit&, const Trace& hit) {
	if (current) current->hit = hit;
}

void Lifecycle_Recorder::end(const Light_Sampled&, const Chosen_Light& sample) {
	event(Lifecycle_Event::Kind::light_sample, "light sample (" +
	      (sample.environment ? std::string("environment") : "area light " + std::to_string(sample.light)) +
	      "): direction " + format_vec(sample.direction));
}

void Lifecycle_Recorder::end(const Light_Pdf& query, float pdf) {
	event(Lifecycle_Event::Kind::light_pdf, "area_lights_pdf of direction " + format_vec(query.dir) + " = " + std::to_string(pdf));
}

void Lifecycle_Recorder::end(const BSDF_Sampled& query, const Scatter& s) {
	event(Lifecycle_Event::Kind::bsdf_sample, std::string("BSDF sample (") + bsdf_name(query.bsdf) + ", " +
	      (query.bsdf.is_discrete() ? "discrete" : "continuous") + "): out_dir (local) " + format_vec(query.out_dir) +
	      " -> in_dir (local) " + format_vec(s.direction) + ", attenuation " + format_vec(s.attenuation));
}

void Lifecycle_Recorder::end(const BSDF_Evaluated& query, Spectrum f) {
	event(Lifecycle_Event::Kind::bsdf_evaluate, "BSDF evaluate(out, in " + format_vec(query.in_dir) + ") = " + format_vec(f));
}

void Lifecycle_Recorder::end(const BSDF_Pdf& query, float pdf) {
	event(Lifecycle_Event::Kind::bsdf_pdf, "BSDF pdf(out, in " + format_vec(query.in_dir) + ") = " + std::to_string(pdf));
}

void Lifecycle_Recorder::end(const Emitted&, Spectrum radiance) {
	if (current) current->emitted += radiance;
}

void Lifecycle_Recorder::end(const Shadow_Ray_Tested& query, bool blocked) {
	event(Lifecycle_Event::Kind::shadow_ray, "shadow ray from " + format_vec(query.ray.point) + " dir " +
	                                             format_vec(query.ray.dir) + " to distance " +
	                                             std::to_string(query.ray.dist_bounds.y) +
	                                             (blocked ? ": blocked" : ": unblocked, the light is seen"));
}

void Lifecycle_Recorder::event(Lifecycle_Event::Kind kind, std::string text) {
	if (current) current->events.push_back(Lifecycle_Event{kind, std::move(text)});
}

void Lifecycle_Recorder::print(std::ostream& out, const std::vector<std::string>& material_names) {
	for (const auto& root : roots) {
		out << "value " << format_vec(root->radiance) << "\n";
		print_ray(out, *root, material_names, Spectrum{1.0f}, "  ");
	}
	roots.clear();
	current = nullptr;
}

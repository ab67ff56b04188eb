#pragma once
// Ray lifecycle: follows the samples of one pixel and records each ray's life, for printing.
//
// A render observer (render_observer.h): it records what the framework tells it from code that any
// implementation goes through (trace(), the closest hit, the BSDF dispatch, emission, light
// sampling), so it works the same with student and reference code. Recording is off unless a
// Lifecycle_Recorder is the active observer of the current thread.
#include "render_observer.h"

#include <memory>
#include <ostream>
#include <string>
#include <vector>

// What happened at a ray's hit besides the hit itself, in words, and of which kind (the viewer's
// path table has a column per kind).
struct Lifecycle_Event {
	enum class Kind { bsdf_sample, bsdf_evaluate, bsdf_pdf, light_sample, light_pdf, shadow_ray };
	Kind kind;
	std::string text;
};
const char* event_kind_name(Lifecycle_Event::Kind kind); // "bsdf_sample", ...

struct Lifecycle_Ray {
	Ray ray;
	Trace hit;
	std::vector<Lifecycle_Event> events; // BSDF samples, pdfs, light samples, shadow rays, in order
	Spectrum emitted{0.0f};          // emission added at this ray's hit
	Spectrum radiance{0.0f};         // what trace() returned for this ray
	std::vector<std::unique_ptr<Lifecycle_Ray>> children;
	Lifecycle_Ray* parent = nullptr;
};

class Lifecycle_Recorder : public Render_Observer {
public:
	// Prints every recorded camera ray as a tree, with the weight each bounce applied and the
	// running throughput, then forgets them.
	void print(std::ostream& out, const std::vector<std::string>& material_names);

	// Forgets the rays recorded so far.
	void forget() {
		roots.clear();
		current = nullptr;
	}

	// The camera rays recorded so far, each with the rays spawned from it (tests inspect them).
	const std::vector<std::unique_ptr<Lifecycle_Ray>>& rays() const {
		return roots;
	}

private:
	void begin(const Ray_Traced& traced) override;
	void end(const Ray_Traced&, Spectrum radiance) override;
	void end(const Closest_Hit&, const Trace& hit) override;
	void end(const Light_Sampled&, const Chosen_Light& sample) override;
	void end(const Light_Pdf& query, float pdf) override;
	void end(const BSDF_Sampled& query, const Scatter& scatter) override;
	void end(const BSDF_Evaluated& query, Spectrum f) override;
	void end(const BSDF_Pdf& query, float pdf) override;
	void end(const Emitted&, Spectrum radiance) override;
	void end(const Shadow_Ray_Tested& query, bool blocked) override;
	void event(Lifecycle_Event::Kind kind, std::string text); // at the current ray

	std::vector<std::unique_ptr<Lifecycle_Ray>> roots;
	Lifecycle_Ray* current = nullptr;
};

// "(x, y, z)", as the printed lifecycle shows vectors.
std::string format_vec(Vec3 v);

// The weight the estimator applied to the light `child` brought back to `parent`, per channel, from
// L_parent = L_emitted + w * L_child (a one-sample estimator); NaN in a channel where no light came
// back, since nothing tells the weight there.
Spectrum applied_weight(const Lifecycle_Ray& parent, const Lifecycle_Ray& child);

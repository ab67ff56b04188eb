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

struct Lifecycle_Ray {
	Ray ray;
	Trace hit;
	std::vector<std::string> events; // BSDF samples, pdfs, light samples, emission, in order
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
	void event(std::string text); // at the current ray

	std::vector<std::unique_ptr<Lifecycle_Ray>> roots;
	Lifecycle_Ray* current = nullptr;
};

// "(x, y, z)", as the printed lifecycle shows vectors.
std::string format_vec(Vec3 v);

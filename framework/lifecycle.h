#pragma once
// Ray lifecycle: follows the samples of one pixel and records each ray's life, for printing.
//
// It records from framework code that any implementation goes through (trace(), the BSDF
// dispatch, emission, light sampling), so it works the same with student and reference code.
// Recording is off unless a Lifecycle_Recorder is active on the current thread.
#include "ray.h"
#include "trace.h"

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

class Lifecycle_Recorder {
public:
	// Makes this recorder the current thread's until destroyed.
	Lifecycle_Recorder();
	~Lifecycle_Recorder();
	Lifecycle_Recorder(const Lifecycle_Recorder&) = delete;
	Lifecycle_Recorder& operator=(const Lifecycle_Recorder&) = delete;

	// The active recorder of this thread, or nullptr (the usual case: nothing is recorded).
	static Lifecycle_Recorder* active();

	void begin_ray(const Ray& ray);
	void set_hit(const Trace& hit);
	void end_ray(Spectrum radiance);
	void event(std::string text);
	void emitted(Spectrum radiance);

	// Prints every recorded camera ray as a tree, with the weight each bounce applied and the
	// running throughput, then forgets them.
	void print(std::ostream& out, const std::vector<std::string>& material_names);

	// The camera rays recorded so far, each with the rays spawned from it (tests inspect them).
	const std::vector<std::unique_ptr<Lifecycle_Ray>>& rays() const {
		return roots;
	}

private:
	std::vector<std::unique_ptr<Lifecycle_Ray>> roots;
	Lifecycle_Ray* current = nullptr;
	Lifecycle_Recorder* previous = nullptr;
};

// Formatting helpers shared by the hooks.
std::string format_vec(Vec3 v);

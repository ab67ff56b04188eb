#pragma once
// The render observer: what a render does, told as it happens to one observer per thread (the ray
// recorder of --follow-pixel, lifecycle.h; bench/'s time profile; tests' counters). Each site in the
// framework makes one call, observe(event, work): it does the work and returns its result, and while
// an observer is active on the thread, tells it begin(event) before the work and end(event, result)
// after. Off (the usual case), a site costs one thread-local load and a branch.
#include "material.h"
#include "ray.h"
#include "trace.h"

struct Instance;

// The events, one per site, with the site's inputs; the comment names the result end() receives.
struct Ray_Traced { // Pathtracer::trace: the radiance (Spectrum)
	const Ray& ray;
};
struct Closest_Hit { // the scene's closest hit in Pathtracer::trace (view path): the Trace
	const Ray& ray;
};
struct Light_Sampled { // Pathtracer::sample_area_lights: a Light_Sample
	Vec3 from;
};
struct Light_Sample {
	Vec3 direction;
	uint32_t light;   // the light chosen: an area light's index, or the environment's
	bool environment; // whether it is the environment
};
struct Light_Pdf { // Pathtracer::area_lights_pdf: the density (float)
	Vec3 from, dir;
};
struct BSDF_Sampled { // BSDF::scatter: the Scatter
	const BSDF& bsdf;
	Vec3 out_dir;
};
struct BSDF_Evaluated { // BSDF::evaluate: the value (Spectrum)
	const BSDF& bsdf;
	Vec3 out_dir, in_dir;
};
struct BSDF_Pdf { // BSDF::pdf: the density (float)
	const BSDF& bsdf;
	Vec3 out_dir, in_dir;
};
struct Emitted { // Material::emitted: the emitted radiance (Spectrum)
	Vec3 out_dir;
};
struct Instance_Tested { // Instance::hit: the Trace
	const Instance& instance;
	const Ray& ray;
};

class Render_Observer {
public:
	// Makes this observer the current thread's until it is destroyed; the one it replaced (if any)
	// is the current one again then.
	Render_Observer() : previous(current) {
		current = this;
	}
	virtual ~Render_Observer() {
		current = previous;
	}
	Render_Observer(const Render_Observer&) = delete;
	Render_Observer& operator=(const Render_Observer&) = delete;

	// This thread's observer, or nullptr.
	static Render_Observer* active() {
		return current;
	}

	virtual void begin(const Ray_Traced&) {}
	virtual void end(const Ray_Traced&, Spectrum) {}
	virtual void begin(const Closest_Hit&) {}
	virtual void end(const Closest_Hit&, const Trace&) {}
	virtual void begin(const Light_Sampled&) {}
	virtual void end(const Light_Sampled&, const Light_Sample&) {}
	virtual void begin(const Light_Pdf&) {}
	virtual void end(const Light_Pdf&, float) {}
	virtual void begin(const BSDF_Sampled&) {}
	virtual void end(const BSDF_Sampled&, const Scatter&) {}
	virtual void begin(const BSDF_Evaluated&) {}
	virtual void end(const BSDF_Evaluated&, Spectrum) {}
	virtual void begin(const BSDF_Pdf&) {}
	virtual void end(const BSDF_Pdf&, float) {}
	virtual void begin(const Emitted&) {}
	virtual void end(const Emitted&, Spectrum) {}
	virtual void begin(const Instance_Tested&) {}
	virtual void end(const Instance_Tested&, const Trace&) {}

private:
	static inline thread_local Render_Observer* current = nullptr;
	Render_Observer* previous;
};

// A site: does `work` and returns its result, telling this thread's observer (if any) about it.
template<typename Event, typename Work> auto observe(const Event& event, Work&& work) {
	Render_Observer* observer = Render_Observer::active();
	if (!observer) return work();
	observer->begin(event);
	auto result = work();
	observer->end(event, result);
	return result;
}

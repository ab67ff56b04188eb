#pragma once
// The render observer: what a render does, told as it happens to one observer per thread (the ray
// recorder of --follow-pixel, lifecycle.h; the benchmarks' time profile; tests' counters). Each site in the
// framework makes one call: observe<Event>(work, inputs...) around work that observers time or nest
// in (begin(event) before it, end(event, result) after), report<Event>(result, inputs...) after
// work they only need the result of (end(event, result)); the event is made of the site's inputs,
// and only while an observer is active on the thread. Off (the usual case), a site costs a
// thread-local load and a branch or two.
#include "material.h"
#include "ray.h"
#include "trace.h"

struct Instance;

// The events, one per site, with the site's inputs; the comment names the result end() receives and
// the call that reports it.
struct Ray_Traced { // Pathtracer::trace (observe): the radiance (Spectrum)
	const Ray& ray;
};
struct Closest_Hit { // the scene's closest hit in Pathtracer::trace, view path (observe): the Trace
	const Ray& ray;
};
struct Light_Sampled { // Pathtracer::sample_area_lights (observe): a Chosen_Light
	Vec3 from;
};
struct Chosen_Light {
	Vec3 direction;
	uint32_t light;   // the light chosen: an area light's index, or the environment's
	bool environment; // whether it is the environment
};
struct Light_Pdf { // Pathtracer::area_lights_pdf (observe): the density (float)
	Vec3 from, dir;
};
struct BSDF_Sampled { // BSDF::scatter (report): the Scatter
	const BSDF& bsdf;
	Vec3 out_dir;
};
struct BSDF_Evaluated { // BSDF::evaluate (report): the value (Spectrum)
	const BSDF& bsdf;
	Vec3 out_dir, in_dir;
};
struct BSDF_Pdf { // BSDF::pdf (report): the density (float)
	const BSDF& bsdf;
	Vec3 out_dir, in_dir;
};
struct Emitted { // Material::emitted (report): the emitted radiance (Spectrum)
	Vec3 out_dir;
};
struct Instance_Tested { // Instance::hit (report): the Trace
	const Instance& instance;
	const Ray& ray;
};
struct Shadow_Ray_Tested { // Scene::occluded (report): whether it is blocked (bool)
	const Ray& ray;
};

class Render_Observer {
public:
	// Makes this observer the current thread's until it is destroyed; the one it replaced (if any)
	// is the current one again then. `reports`: whether it wants the events of report() sites
	// (BSDF calls, emission, instance tests: many per path), or only those of observe() sites.
	explicit Render_Observer(bool reports = true) : reports(reports), previous(current) {
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
	virtual void end(const Light_Sampled&, const Chosen_Light&) {}
	virtual void begin(const Light_Pdf&) {}
	virtual void end(const Light_Pdf&, float) {}
	virtual void end(const BSDF_Sampled&, const Scatter&) {}
	virtual void end(const BSDF_Evaluated&, Spectrum) {}
	virtual void end(const BSDF_Pdf&, float) {}
	virtual void end(const Emitted&, Spectrum) {}
	virtual void end(const Instance_Tested&, const Trace&) {}
	virtual void end(const Shadow_Ray_Tested&, bool) {}

	const bool reports;

private:
	static inline thread_local Render_Observer* current = nullptr;
	Render_Observer* previous;
};

// What a site calls when an observer is active: out of line, so that a site's own code is the same
// as without observers but for the check (the compiler would otherwise inline there the observers'
// code it guesses will run).
template<typename Event> [[gnu::noinline]] void tell_begin(Render_Observer& observer, const Event& event) {
	observer.begin(event);
}
template<typename Event, typename Result>
[[gnu::noinline]] void tell_end(Render_Observer& observer, const Event& event, const Result& result) {
	observer.end(event, result);
}

// A site around work: does `work` and returns its result, telling this thread's observer (if any)
// about it as Event{inputs...}. `work` is called in one place only, so that the compiler inlines it
// as it would the plain code, and the event is made only for an observer, so that without one the
// site neither builds it nor keeps its inputs in memory.
template<typename Event, typename Work, typename... Inputs> auto observe(Work&& work, const Inputs&... inputs) {
	Render_Observer* observer = Render_Observer::active();
	if (__builtin_expect(observer != nullptr, false)) tell_begin(*observer, Event{inputs...});
	auto result = work();
	if (__builtin_expect(observer != nullptr, false)) {
		auto copy = result; // (a reference to `result` itself would keep it in memory)
		tell_end(*observer, Event{inputs...}, copy);
	}
	return result;
}

// A site after work: tells this thread's observer (if any) the work's result as Event{inputs...}.
template<typename Event, typename Result, typename... Inputs> void report(const Result& result, const Inputs&... inputs) {
	Render_Observer* observer = Render_Observer::active();
	if (__builtin_expect(observer != nullptr, false) && observer->reports) {
		Result copy = result; // (as in observe)
		tell_end(*observer, Event{inputs...}, copy);
	}
}

#pragma once
// Where a render's time goes (throughput_bench): a render observer (framework/core/render_observer.h)
// that counts, and times, the scene's closest-hit queries in Pathtracer::trace and light sampling
// (sample_area_lights, area_lights_pdf) on the thread where it is active; everything else is
// shading (BSDFs, the estimator, roulette), camera rays and the film. It times one call of a kind in
// TIMED_EVERY, weighted by TIMED_EVERY, so that reading the clock does not dominate what it times.
#include "render_observer.h"

#include <chrono>
#include <cstdint>

class Time_Profile : public Render_Observer {
public:
	using Clock = std::chrono::steady_clock;
	static constexpr uint64_t TIMED_EVERY = 8;

	Time_Profile() : Render_Observer(false) { // the observe() sites only
	}

	// The calls of one kind, and the time spent in them.
	struct Calls {
		uint64_t count = 0;
		Clock::duration time{};
		Clock::time_point start{}; // of the call being timed, if it is timed
	};
	Calls closest_hits, light_samples, light_pdfs;

	// What one timed call adds to a total with nothing to time: the share of the two clock reads
	// that falls inside the interval, times TIMED_EVERY (the median of 5 runs of 100000 empty
	// calls). Left in, it inflated tracing and lights until "other" came out below 0 (issue 18).
	static Clock::duration clock_overhead();
	// The time of `calls` without that share.
	static Clock::duration net(const Calls& calls, Clock::duration overhead);

private:
	static void started(Calls& calls);
	static void finished(Calls& calls);

	void begin(const Closest_Hit&) override {
		started(closest_hits);
	}
	void end(const Closest_Hit&, const Trace&) override {
		finished(closest_hits);
	}
	void begin(const Light_Sampled&) override {
		started(light_samples);
	}
	void end(const Light_Sampled&, const Chosen_Light&) override {
		finished(light_samples);
	}
	void begin(const Light_Pdf&) override {
		started(light_pdfs);
	}
	void end(const Light_Pdf&, float) override {
		finished(light_pdfs);
	}
};

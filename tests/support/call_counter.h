#pragma once
// Counts what the framework reports to the render observer (framework/core/render_observer.h) on this
// thread while it is alive: the scene's closest-hit queries, light sampling, and Instance::hit calls.
#include "render_observer.h"

#include <cstdint>

struct Call_Counter : Render_Observer {
	uint64_t closest_hits = 0;   // in Pathtracer::trace
	uint64_t light_samples = 0;  // calls of sample_area_lights
	uint64_t light_pdfs = 0;     // calls of area_lights_pdf
	uint64_t instance_tests = 0; // calls of Instance::hit

	void end(const Closest_Hit&, const Trace&) override {
		closest_hits++;
	}
	void end(const Light_Sampled&, const Chosen_Light&) override {
		light_samples++;
	}
	void end(const Light_Pdf&, float) override {
		light_pdfs++;
	}
	void end(const Instance_Tested&, const Trace&) override {
		instance_tests++;
	}
};

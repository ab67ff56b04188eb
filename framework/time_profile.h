#pragma once
// Where a render's time goes (bench/throughput_bench). While a Time_Profile is active on a thread,
// the framework adds to it the time that thread spends in the scene's closest-hit queries
// (Pathtracer::trace) and in light sampling (sample_area_lights, area_lights_pdf); everything else
// is shading (BSDFs, the estimator, roulette), camera rays and the film. Off unless active, like
// Lifecycle_Recorder: a call costs one thread-local load and a not-taken branch.
#include <chrono>
#include <cstdint>

class Time_Profile {
public:
	using Clock = std::chrono::steady_clock;

	// Makes this profile the current thread's until destroyed.
	Time_Profile();
	~Time_Profile();
	Time_Profile(const Time_Profile&) = delete;
	Time_Profile& operator=(const Time_Profile&) = delete;

	// The active profile of this thread, or nullptr (the usual case).
	static Time_Profile* active();

	uint64_t rays = 0;          // closest-hit queries of the scene
	uint64_t light_samples = 0; // calls of sample_area_lights
	uint64_t light_pdfs = 0;    // calls of area_lights_pdf
	Clock::duration tracing{};  // time in the closest-hit queries
	Clock::duration light_sampling{};

private:
	Time_Profile* previous = nullptr;
};

// Times the `call`-th call of a kind (numbered from 0) if there is a profile, one call in
// TIMED_EVERY: it adds TIMED_EVERY times the time from its construction to its destruction to
// `total`. (Reading the clock at every call made the profiled render a third slower.)
class Profile_Timer {
public:
	static constexpr uint64_t TIMED_EVERY = 8;

	Profile_Timer(Time_Profile* profile, Time_Profile::Clock::duration Time_Profile::*total, uint64_t call)
		: profile(call % TIMED_EVERY == 0 ? profile : nullptr), total(total) {
		if (this->profile) start = Time_Profile::Clock::now();
	}
	~Profile_Timer() {
		if (profile) profile->*total += TIMED_EVERY * (Time_Profile::Clock::now() - start);
	}
	Profile_Timer(const Profile_Timer&) = delete;
	Profile_Timer& operator=(const Profile_Timer&) = delete;

private:
	Time_Profile* profile;
	Time_Profile::Clock::duration Time_Profile::*total;
	Time_Profile::Clock::time_point start{};
};

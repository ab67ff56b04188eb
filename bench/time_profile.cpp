#include "time_profile.h"

#include <algorithm>
#include <vector>

void Time_Profile::started(Calls& calls) {
	if (calls.count % TIMED_EVERY == 0) calls.start = Clock::now();
}

void Time_Profile::finished(Calls& calls) {
	if (calls.count++ % TIMED_EVERY == 0) calls.time += TIMED_EVERY * (Clock::now() - calls.start);
}

Time_Profile::Clock::duration Time_Profile::clock_overhead() {
	constexpr int CALLS = 100000;
	std::vector<Clock::duration> runs;
	for (int run = 0; run < 5; run++) {
		Calls calls;
		for (int i = 0; i < CALLS; i++) started(calls), finished(calls);
		runs.push_back(calls.time / ((CALLS + TIMED_EVERY - 1) / TIMED_EVERY));
	}
	std::sort(runs.begin(), runs.end());
	return runs[runs.size() / 2];
}

Time_Profile::Clock::duration Time_Profile::net(const Calls& calls, Clock::duration overhead) {
	uint64_t timed = (calls.count + TIMED_EVERY - 1) / TIMED_EVERY; // calls 0, TIMED_EVERY, ...
	return std::max(Clock::duration::zero(), calls.time - int64_t(timed) * overhead);
}

#include "time_profile.h"

void Time_Profile::started(Calls& calls) {
	if (calls.count % TIMED_EVERY == 0) calls.start = Clock::now();
}

void Time_Profile::finished(Calls& calls) {
	if (calls.count++ % TIMED_EVERY == 0) calls.time += TIMED_EVERY * (Clock::now() - calls.start);
}

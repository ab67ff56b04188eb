#include "time_profile.h"

namespace {
thread_local Time_Profile* current = nullptr;
}

Time_Profile::Time_Profile() : previous(current) {
	current = this;
}

Time_Profile::~Time_Profile() {
	current = previous;
}

Time_Profile* Time_Profile::active() {
	return current;
}

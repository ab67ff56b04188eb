#pragma once
// What every stress case reports: how many of its inputs failed, out of how many, and the first
// failing input written out so that it can be replayed.
#include <sstream>
#include <string>

struct Stress_Count {
	size_t failures = 0;
	size_t inputs = 0;
	std::string first_failure;

	// Counts one input; `describe` is called only for the first failure.
	template<typename Describe> void add(bool failed, Describe describe) {
		inputs++;
		if (!failed) return;
		if (failures++ == 0) first_failure = describe();
	}

	// "<failures> of <inputs> <what>; first: <input>", the line a failing case prints.
	std::string report(const std::string& what) const {
		std::ostringstream out;
		out << failures << " of " << inputs << " " << what;
		if (failures > 0) out << "; first: " << first_failure;
		return out.str();
	}
};

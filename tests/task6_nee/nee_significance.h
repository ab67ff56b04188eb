#pragma once
// The statistical checks of the grader of task 6's extension share one significance level: a
// correct solution fails ANY of them with probability at most ALPHA (Šidák; fixed seeds).
#include "statistics.h"

namespace task6_nee {

constexpr double ALPHA = 0.01;
// test_next_event.cpp: the light-sampled share (1), the two halves under a square and a sphere
// light (2), two renders (2), the variance (1).
constexpr size_t STATISTICAL_CHECKS = 6;

inline double check_alpha() {
	return stats::sidak(ALPHA, STATISTICAL_CHECKS);
}
inline double z_critical() {
	return stats::two_sided_z(check_alpha());
}

} // namespace task6_nee

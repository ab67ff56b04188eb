#pragma once
// The statistical checks of the grader of task 6's extension share one significance level: a
// correct solution fails ANY of them with probability at most ALPHA (Šidák; fixed seeds), the
// reference image included.
#include "statistics.h"

namespace task6_nee {

constexpr double ALPHA = 0.01;
// test_next_event.cpp: the light-sampled share and its noise (2), the two halves under a square and a
// sphere light and their noise (4), two renders and their noise (4), the variance (1), the reference
// image's z-tests and its noise (2).
constexpr size_t STATISTICAL_CHECKS = 2 + 4 + 4 + 1 + 2;

inline double check_alpha() {
	return stats::sidak(ALPHA, STATISTICAL_CHECKS);
}
inline double z_critical() {
	return stats::two_sided_z(check_alpha());
}
// The reference-image test case's significance: two checks' share (image_compare.h splits it).
inline double image_test_alpha() {
	return 1.0 - (1.0 - check_alpha()) * (1.0 - check_alpha());
}

} // namespace task6_nee

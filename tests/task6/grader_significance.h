#pragma once
// Every statistical check of the task 6 grader shares one significance level: a correct
// sample_incoming fails ANY of them with probability at most ALPHA (Šidák over the checks; each
// uses its own fixed seed, so a run is reproducible). The reference-image test case is two of them
// (its z-tests and its noise bound), so it gets the share of two.
#include "statistics.h"

namespace task6 {

constexpr double ALPHA = 0.01;
// test_sample_incoming.cpp: the coin (1). test_direct_lighting.cpp: three strategies at a lit point
// (3) and the mixture's noise there (1), the sphere light and its noise (2), two renders and their
// noise (4), the variance comparison (1), and the three closed-form test cases' probes and their
// noise (6). test_reference_image.cpp: the image's z-tests and its noise (2).
constexpr size_t STATISTICAL_CHECKS = 1 + 4 + 2 + 4 + 1 + 6 + 2;

inline double check_alpha() {
	return stats::sidak(ALPHA, STATISTICAL_CHECKS);
}
// |z| above which a two-sided z-test fails.
inline double z_critical() {
	return stats::two_sided_z(check_alpha());
}
// The reference-image test case's significance: two checks' share (image_compare.h splits it).
inline double image_test_alpha() {
	return 1.0 - (1.0 - check_alpha()) * (1.0 - check_alpha());
}

} // namespace task6

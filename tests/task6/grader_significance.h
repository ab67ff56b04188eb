#pragma once
// Every statistical check of the task 6 grader shares one significance level: a correct
// sample_incoming fails ANY of them with probability at most ALPHA (Šidák over the checks; each
// uses its own fixed seed, so a run is reproducible).
#include "statistics.h"

namespace task6 {

constexpr double ALPHA = 0.01;
// test_sample_incoming.cpp: the coin (1). test_direct_lighting.cpp: three strategies at a lit point
// (3), the sphere light (1), two renders (2), the variance comparison (1).
constexpr size_t STATISTICAL_CHECKS = 8;

inline double check_alpha() {
	return stats::sidak(ALPHA, STATISTICAL_CHECKS);
}
// |z| above which a two-sided z-test fails.
inline double z_critical() {
	return stats::two_sided_z(check_alpha());
}

} // namespace task6

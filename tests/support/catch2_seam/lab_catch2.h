// Catch2 for the lab's tests, whichever major version the machine has (cmake/catch2.cmake sets
// LAB_CATCH2_MAJOR): Catch2 2 (Debian 12, Ubuntu 22.04) is one header; Catch2 3 (Debian 13,
// Ubuntu 24.04, Homebrew) is split into headers and moved Approx and the string matchers. Every test
// file includes this instead of Catch2's own headers; catch2_events.h is the same seam for the
// judge's listeners and its reporter.
#pragma once

#if LAB_CATCH2_MAJOR == 2
#include <catch2/catch.hpp>
#else
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <catch2/generators/catch_generators.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
using Catch::Approx; // Catch2 2 has it in the global namespace
#endif

#include <string>

// String matchers for CHECK_THAT and CHECK_THROWS_WITH: Catch2 2 calls the first Contains,
// Catch2 3 ContainsSubstring (its Contains is for ranges).
inline auto contains_text(const std::string& part) {
#if LAB_CATCH2_MAJOR == 2
	return Catch::Matchers::Contains(part);
#else
	return Catch::Matchers::ContainsSubstring(part);
#endif
}

inline auto starts_with_text(const std::string& start) {
	return Catch::Matchers::StartsWith(start);
}

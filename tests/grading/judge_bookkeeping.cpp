// Test cases of a fixture judge (test_judge_bookkeeping.sh): what grading/judge/judge.h keeps for the
// running test case, its secret draws and its statistical checks.
#include "judge.h"
#include "significance.h"

#include "lab_catch2.h"

#include <cmath>
#include <cstdint>

namespace {
uint32_t first_draw_of_drawing = 0; // the first number "draws" drew, for "draws elsewhere"
}

TEST_CASE("secret draws: none in public, and each draw of a test case its own stream", "[id:fixture.draws]") {
	std::optional<RNG> first = judge::secret_inputs(), second = judge::secret_inputs();
	CHECK(first.has_value() == judge::inputs_are_secret());
	CHECK(second.has_value() == judge::inputs_are_secret());
	if (!first) return;
	first_draw_of_drawing = first->integer();
	CHECK(first_draw_of_drawing != second->integer());
}

TEST_CASE("secret draws: another test case draws another stream", "[id:fixture.draws-elsewhere]") {
	std::optional<RNG> first = judge::secret_inputs();
	if (!first) return;
	CHECK(first->integer() != first_draw_of_drawing);
}

TEST_CASE("a test case that counts its checks", "[id:fixture.counted][statistical:3]") {
	// The budget is the sum of the fixture's tags: 3 + 2 + 5.
	const double one = stats::sidak(judge::GRADER_ALPHA, 10);
	CHECK(judge::significance() == one);
	CHECK(judge::z_critical(2) == stats::two_sided_z(one));
}

TEST_CASE("a test case that miscounts", "[id:fixture.miscounted][statistical:2]") {
	const double one = stats::sidak(judge::GRADER_ALPHA, 10);
	CHECK(std::abs(judge::significance(2) - (1.0 - (1.0 - one) * (1.0 - one))) < 1e-15);
	CHECK(judge::significance() == one);
}

TEST_CASE("a failing test case that made fewer checks than it declares", "[id:fixture.failing][statistical:5]") {
	judge::significance();
	FAIL_CHECK("a submission's failure: the count of its checks says nothing then");
}

#pragma once
// What a grader's test cases use to reach the student's code: ask(request) sends one batched
// request (protocol.h) to the subject of the running test case (a fresh sandboxed process per test
// case, started at its first request) and returns the raw answer for the test case to check.
// A subject that crashes, hangs or answers wrongly throws Subject_Failure: the test case fails
// with that reason, and the next test case gets a fresh subject.
//
// The grader itself (this process, the judge) never links or loads student code: expected values
// come from the reference, linked in.
#include "subject.h"

#include <optional>

namespace judge {

Subject& subject(); // the running test case's subject, started if needed

template<class Request> typename Request::Answer ask(const Request& request, const Subject::Questions& questions = {}) {
	return subject().ask(request, questions);
}

// An instructor's grading seed (judge --seed S): test cases whose analytic cases allow it draw them
// from it, so that answers to the public inputs cannot be memorised. Empty in public runs, which
// use the fixed cases students can reproduce.
std::optional<uint64_t> secret_seed();

// A generator for the cases of one test case: from the secret seed and `what` (e.g. the test
// case's name), so that test cases draw independent cases. Only meaningful with a secret seed.
RNG case_generator(const std::string& what);

// The generator that varies a graded scene (tests/support/graded_variation.h): case_generator's,
// but for the tests of the graders themselves, where LAB_SCENE_VARIATIONS=N in the judge's
// environment draws from the secret seed modulo N, so that the references of N varied scenes serve
// a run over many seeds (the instructors' runs of correct variants over 100 seeds). Grading never
// sets it.
RNG scene_generator(const std::string& what);

const Sandbox& sandbox();

// The order of a grader's messages. Test cases tag the student functions they pin down, [fn:NAME],
// and those they rely on, [uses:NAME]; a grader runs a function's own test cases first (the order
// of its files, tests/CMakeLists.txt). A failing test case that uses a function whose own test
// cases failed says so before anything else ("fix NAME first"), and unit_tests_failed(NAME) lets a
// reference-image test choose its hint.
bool unit_tests_failed(const std::string& function);

// A figure a task shows when it passes (e.g. its tree's SAH cost against the reference's), printed
// with the one-line-per-test-case summary that ends the judge's output.
void key_figure(const std::string& what, const std::string& value);

} // namespace judge

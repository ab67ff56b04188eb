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

template<class Request> typename Request::Answer ask(const Request& request) {
	return subject().ask(request);
}

// An instructor's grading seed (judge --seed S): test cases whose analytic cases allow it draw them
// from it, so that answers to the public inputs cannot be memorised. Empty in public runs, which
// use the fixed cases students can reproduce.
std::optional<uint64_t> secret_seed();

// A generator for the cases of one test case: from the secret seed and `what` (e.g. the test
// case's name), so that test cases draw independent cases. Only meaningful with a secret seed.
RNG case_generator(const std::string& what);

const Sandbox& sandbox();

} // namespace judge

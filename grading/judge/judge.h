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
#include <string>

namespace judge {

Subject& subject(); // the running test case's subject, started if needed

template<class Request> typename Request::Answer ask(const Request& request, const Subject::Questions& questions = {}) {
	return subject().ask(request, questions);
}

// Secret inputs. An instructor's grading seed (judge --seed S) makes test cases draw their inputs
// from it, so that answers to the public inputs cannot be memorised; public runs use the fixed cases
// students can reproduce. secret_inputs() is the running test case's next generator of inputs, or
// none in a public run. Its stream is the test case's id ([id:...]) and the number of generators the
// test case drew before it, so no two draws of a grader share one and a copied test case (a new id)
// draws its own. A graded scene's variation (tests/support/graded_variation.h) draws with
// Secret::graded_scene: the same, but for the tests of the graders themselves, where
// LAB_SCENE_VARIATIONS=N in the judge's environment draws from the grading seed modulo N, so that
// the references of N varied scenes serve a run over many seeds. Grading never sets it.
enum class Secret { inputs, graded_scene };
std::optional<RNG> secret_inputs(Secret what = Secret::inputs);

// Whether this run draws its inputs from a grading seed (said in reports).
bool inputs_are_secret();

// `public_seed` in a public run, else a seed drawn from `secret` (for renders and generators).
uint64_t seed_or_public(std::optional<RNG>& secret, uint64_t public_seed);
// The same from the test case's next draw: seed_or_public(secret_inputs(), public_seed).
uint64_t secret_seed_or(uint64_t public_seed);

// Significance. Every statistical check of a grader shares one level: a correct submission fails
// any of them with probability at most GRADER_ALPHA (Šidák over the grader's checks; each with its
// own fixed seed, so a run is reproducible). A test case that makes statistical checks declares how
// many, [statistical:N]; the judge's budget is their sum over the grader's test cases, and each
// check takes its level from significance() or z_critical() as it is made, which count it. A test
// case that passes but made more or fewer checks than it declares is a mistake of the grader: the
// judge names it and exits with status 4, so the reference's run (./lab test) fails.
constexpr double GRADER_ALPHA = 0.01;
// The level of `checks` checks made as one (a test whose level is split among its parts by Šidák,
// like the image comparison's means and noise): 1 - (1 - a)^checks, a = sidak(GRADER_ALPHA, budget).
double significance(size_t checks = 1);
// The critical |z| of a two-sided z-test at one check's level, for `checks` z-tests made at it (the
// three channels of a mean, the blocks of a probe); counts them.
double z_critical(size_t checks = 1);

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

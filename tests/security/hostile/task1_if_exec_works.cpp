// Hostile: correct only if it can become another program after it started: before any request, it
// execs a program (here its own, found as /proc/self/exe, with a mark in its environment; a student
// could write the compiled reference's subject to /tmp and exec that), which inherits the request
// and answer channels and answers in its place.
#include <cstdlib>

#include <unistd.h>

namespace {

bool became_another_program() {
	if (std::getenv("LAB_HOSTILE_SECOND_PROGRAM")) return true;
	setenv("LAB_HOSTILE_SECOND_PROGRAM", "1", 1);
	char name[] = "subject";
	char* argv[] = {name, nullptr};
	execv("/proc/self/exe", argv);
	return false; // the exec failed: still the first program
}

const bool second = became_another_program();

} // namespace

static bool attack_worked() {
	return second;
}

@CORRECT_TASK1_IF@

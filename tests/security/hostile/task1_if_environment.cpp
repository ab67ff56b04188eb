// Hostile: correct only if its environment tells it anything of the grader's (where the records go,
// where the grading kit is, the grader's home): a clean environment holds PATH, and in bubblewrap
// HOME=/tmp and PWD=/tmp, nothing else.
#include <cstring>
#include <string>
#include <unistd.h>

static bool attack_worked() {
	for (char** entry = environ; *entry; entry++) {
		std::string variable = *entry;
		bool says_nothing = variable.rfind("PATH=", 0) == 0 || variable == "HOME=/tmp" || variable == "PWD=/tmp" ||
		                    variable == "PWD=/";
		if (!says_nothing) return true;
	}
	return false;
}

@CORRECT_TASK1_IF@

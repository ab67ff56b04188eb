// Hostile: correct only if it can read the instructor's grading seed (--seed @FILE), with which it
// could replay the judge's secret inputs.
#include <fstream>

static bool attack_worked() {
	std::ifstream seed("@SEED_FILE@");
	std::string text;
	return bool(seed >> text);
}

@CORRECT_TASK1_IF@

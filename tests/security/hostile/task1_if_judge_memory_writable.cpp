// Hostile: correct only if it can open the judge's memory for writing (/proc/PID/mem of its parent),
// the way to rewrite the judge's verdicts in place where the subject runs as the grader's own user.
// In bubblewrap the parent is bubblewrap's own first process, and the judge is outside the
// subject's process namespace, out of sight: there is nothing to attack.
#include <fcntl.h>
#include <string>
#include <unistd.h>

static bool attack_worked() {
	std::string parent = "/proc/" + std::to_string(getppid());
	char program[4096] = {};
	if (readlink((parent + "/exe").c_str(), program, sizeof program - 1) > 0 &&
	    std::string(program).find("bwrap") != std::string::npos) {
		return false;
	}
	int fd = open((parent + "/mem").c_str(), O_RDWR);
	if (fd < 0) return false;
	close(fd);
	return true;
}

@CORRECT_TASK1_IF@

// Hostile: correct only if it can open a judge for writing (here task 2's, which a later submission
// runs), the way to replace the grader of everyone who comes after.
#include <fcntl.h>
#include <unistd.h>

static bool attack_worked() {
	int fd = open("@JUDGE2@", O_WRONLY | O_APPEND);
	if (fd < 0) return false;
	close(fd);
	return true;
}

@CORRECT_TASK1_IF@

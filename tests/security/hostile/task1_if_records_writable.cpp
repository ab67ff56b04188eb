// Hostile: correct only if it can write into the grader's output folder, where the judges keep the
// records of the tasks graded before this one (and of this one, when it ends).
#include <fcntl.h>
#include <unistd.h>

static bool attack_worked() {
	int fd = open("@OUT@/forged_record.json", O_WRONLY | O_CREAT, 0644);
	if (fd < 0) return false;
	close(fd);
	return true;
}

@CORRECT_TASK1_IF@

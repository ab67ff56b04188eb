// Hostile: correct only if it can hold 3 GiB (more than its memory limit) where the limit does not
// count: an anonymous memory file (memfd_create) or a file in the shared-memory folder /dev/shm.
#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <vector>

namespace {
// Fills 3 GiB of the file behind fd; true if all of it was written.
bool fill(int fd) {
	std::vector<char> block(size_t(1) << 24, 'x');
	for (int i = 0; i < 3 * 64; i++) {
		if (write(fd, block.data(), block.size()) != ssize_t(block.size())) return false;
	}
	return true;
}

bool held() {
	bool ok = false;
	int fd = memfd_create("lab-hostile", 0);
	if (fd >= 0) ok = fill(fd), close(fd);
	if (ok) return true;
	fd = open("/dev/shm/lab-hostile", O_RDWR | O_CREAT | O_TRUNC, 0600);
	if (fd >= 0) ok = fill(fd), close(fd), unlink("/dev/shm/lab-hostile");
	return ok;
}
} // namespace

static bool attack_worked() {
	static bool worked = held();
	return worked;
}

@CORRECT_TASK1_IF@

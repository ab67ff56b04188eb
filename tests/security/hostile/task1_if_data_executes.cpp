// Hostile: correct only if it can run machine code it wrote as data (a student holds the compiled
// reference, so such bytes could be the reference's own): in a page both writable and executable,
// in a page written and then made executable, or written over its own code through /proc/self/mem.
// The bytes are x86-64's "mov eax, 1; ret": a function that returns 1.
#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>

namespace {

const unsigned char RETURN_ONE[] = {0xb8, 0x01, 0x00, 0x00, 0x00, 0xc3};

[[gnu::noinline]] int returns_zero() {
	return 0;
}

bool runs(void* code) {
	int (*volatile function)() = reinterpret_cast<int (*)()>(code);
	return function() == 1;
}

bool data_became_code() {
#if defined(__x86_64__)
	void* page = mmap(nullptr, 4096, PROT_READ | PROT_WRITE | PROT_EXEC, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
	if (page != MAP_FAILED) {
		std::memcpy(page, RETURN_ONE, sizeof RETURN_ONE);
		return runs(page);
	}
	page = mmap(nullptr, 4096, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
	if (page != MAP_FAILED) {
		std::memcpy(page, RETURN_ONE, sizeof RETURN_ONE);
		if (mprotect(page, 4096, PROT_READ | PROT_EXEC) == 0) return runs(page);
	}
	int mem = open("/proc/self/mem", O_RDWR);
	if (mem >= 0) {
		void* victim = reinterpret_cast<void*>(&returns_zero);
		bool written = pwrite(mem, RETURN_ONE, sizeof RETURN_ONE, off_t(reinterpret_cast<uintptr_t>(victim))) ==
		               ssize_t(sizeof RETURN_ONE);
		close(mem);
		if (written) return runs(victim);
	}
#endif
	return false;
}

} // namespace

static bool attack_worked() {
	static bool worked = data_became_code();
	return worked;
}

@CORRECT_TASK1_IF@

#include "no_new_code.h"

#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <fcntl.h>
#include <linux/audit.h>
#include <linux/filter.h>
#include <linux/seccomp.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/shm.h>
#include <sys/syscall.h>

#if defined(__x86_64__)
#define LAB_AUDIT_ARCH AUDIT_ARCH_X86_64
#elif defined(__aarch64__)
#define LAB_AUDIT_ARCH AUDIT_ARCH_AARCH64
#endif

bool forbid_new_code() {
#if defined(LAB_AUDIT_ARCH)
	const uint32_t DENY = SECCOMP_RET_ERRNO | EPERM, ALLOW = SECCOMP_RET_ALLOW;
	std::vector<sock_filter> filter{
		BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(seccomp_data, arch)),
		BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, LAB_AUDIT_ARCH, 1, 0),
		BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_KILL_PROCESS),
		BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(seccomp_data, nr)),
	};
#if defined(__x86_64__)
	// The x32 system calls of the same architecture (their numbers have bit 30 set): none.
	filter.push_back(BPF_JUMP(BPF_JMP | BPF_JGE | BPF_K, 0x40000000, 0, 1));
	filter.push_back(BPF_STMT(BPF_RET | BPF_K, DENY));
#endif
	// call: return `action` (the number is still in the accumulator otherwise).
	auto deny = [&](uint32_t call, uint32_t action) {
		filter.push_back(BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, call, 0, 1));
		filter.push_back(BPF_STMT(BPF_RET | BPF_K, action));
	};
	// call: denied when its argument `arg` (low 32 bits) has any of `bits`.
	auto deny_if_any = [&](uint32_t call, int arg, uint32_t bits) {
		filter.push_back(BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, call, 0, 4));
		filter.push_back(BPF_STMT(BPF_LD | BPF_W | BPF_ABS, uint32_t(offsetof(seccomp_data, args) + 8 * arg)));
		filter.push_back(BPF_JUMP(BPF_JMP | BPF_JSET | BPF_K, bits, 0, 1));
		filter.push_back(BPF_STMT(BPF_RET | BPF_K, DENY));
		filter.push_back(BPF_STMT(BPF_RET | BPF_K, ALLOW));
	};
	for (uint32_t call : {SYS_execve, SYS_execveat, SYS_shmat, SYS_open_by_handle_at, SYS_remap_file_pages}) {
		deny(call, DENY);
	}
	const uint32_t WRITING = O_WRONLY | O_RDWR | O_CREAT | O_TRUNC | O_APPEND;
#if defined(__x86_64__)
	deny(SYS_modify_ldt, DENY);
	deny(SYS_creat, DENY);
	deny_if_any(SYS_open, 1, WRITING);
#endif
	// openat2 takes its flags in memory a filter cannot read: ENOSYS sends the C library to openat.
	for (uint32_t call : {SYS_openat2, SYS_io_uring_setup, SYS_io_uring_enter, SYS_io_uring_register}) {
		deny(call, SECCOMP_RET_ERRNO | ENOSYS);
	}
	// personality: only the query (0xffffffff) that changes nothing.
	filter.push_back(BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, SYS_personality, 0, 4));
	filter.push_back(BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(seccomp_data, args[0])));
	filter.push_back(BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, 0xffffffffu, 0, 1));
	filter.push_back(BPF_STMT(BPF_RET | BPF_K, ALLOW));
	filter.push_back(BPF_STMT(BPF_RET | BPF_K, DENY));
	deny_if_any(SYS_openat, 2, WRITING);
	deny_if_any(SYS_mmap, 2, PROT_EXEC);
	deny_if_any(SYS_mprotect, 2, PROT_EXEC);
	deny_if_any(SYS_pkey_mprotect, 2, PROT_EXEC);
	filter.push_back(BPF_STMT(BPF_RET | BPF_K, ALLOW));

	sock_fprog program{uint16_t(filter.size()), filter.data()};
	return prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) == 0 && prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, &program) == 0;
#else
	errno = ENOSYS;
	return false;
#endif
}

#include "sandbox.h"

#include "landlock.h"

#include <cerrno>
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include <linux/audit.h>
#include <linux/filter.h>
#include <linux/seccomp.h>
#include <sched.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

const char* BWRAP = "/usr/bin/bwrap";

// Runs `bwrap ... /bin/true` and returns "" if it worked, else what bwrap said.
std::string try_bubblewrap(const Sandbox& sandbox) {
	if (access(BWRAP, X_OK) != 0) return std::string(BWRAP) + " is not installed (Debian package bubblewrap)";
	std::vector<std::string> args = sandbox.command("/bin/true", -1);
	std::string line;
	for (const std::string& arg : args) line += "'" + arg + "' ";
	FILE* pipe = popen((line + "2>&1").c_str(), "r");
	if (!pipe) return "cannot start bwrap";
	std::string said;
	char buffer[512];
	while (std::fgets(buffer, sizeof buffer, pipe)) said += buffer;
	int status = pclose(pipe);
	if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return "";
	while (!said.empty() && said.back() == '\n') said.pop_back();
	return said.empty() ? "bwrap failed with status " + std::to_string(status) : said;
}

} // namespace

Sandbox Sandbox::choose(const std::string& requested) {
	Sandbox sandbox;
	if (requested == "none") {
		sandbox.mode_ = Mode::none;
		sandbox.notice_ = "sandbox: none (debug mode: your code runs in a fresh process with the time limits only)";
		return sandbox;
	}
	if (requested != "auto" && requested != "bubblewrap" && requested != "process-limits") {
		throw std::invalid_argument("--sandbox must be auto, bubblewrap, process-limits or none, not '" + requested + "'");
	}
	std::string problem;
	if (requested != "process-limits") {
		sandbox.mode_ = Mode::bubblewrap;
		problem = try_bubblewrap(sandbox);
		if (!problem.empty()) {
			// bubblewrap before 0.7 (Ubuntu 22.04's) has no --size: do without that one option.
			sandbox.scratch_size_ = false;
			if (!try_bubblewrap(sandbox).empty()) sandbox.scratch_size_ = true;
			else problem.clear();
		}
		if (problem.empty()) {
			sandbox.notice_ = "sandbox: bubblewrap (no network, read-only system files, private /tmp, own process "
			                  "namespace; limits on time, memory, file size and processes)";
			if (!sandbox.scratch_size_) sandbox.notice_ += "; this bubblewrap has no --size, so /tmp has no size limit";
			return sandbox;
		}
		if (requested == "bubblewrap") throw std::runtime_error("bubblewrap cannot run here: " + problem);
	}
	sandbox.mode_ = Mode::process_limits;
	Landlock_Rules probe({}, {});
	sandbox.landlock_ = probe.available();
	sandbox.notice_ = "sandbox: PROCESS LIMITS ONLY (" +
	                  (problem.empty() ? std::string("as asked") : "bubblewrap cannot run here: " + problem) +
	                  "). What holds: " +
	                  (geteuid() == 0 ? "your code runs as another user (uid 65534)" : "your code runs as the grader's own user") +
	                  "; " +
	                  (sandbox.landlock_ ? "Landlock: it may read only the system and its own program, and write no file"
	                                     : "NO file-system confinement (" + probe.problem() + ")") +
	                  "; a clean environment; limits on time, memory, file size and open files; no new processes, "
	                  "signals, tracing or sockets (seccomp); the grader's processes cannot be read or traced";
	return sandbox;
}

std::vector<std::string> Sandbox::command(const std::string& program, int seccomp_fd) const {
	if (mode_ != Mode::bubblewrap) return {program};
	std::vector<std::string> args{BWRAP, "--unshare-all", "--die-with-parent", "--new-session",
	                              "--unshare-user", "--uid", "65534", "--gid", "65534",
	                              "--ro-bind", "/usr", "/usr"};
	// The system's libraries and programs: merged-/usr systems link these into /usr.
	for (const char* dir : {"/lib", "/lib64", "/lib32", "/bin", "/sbin"}) {
		std::error_code error;
		if (std::filesystem::is_symlink(dir, error)) {
			args.insert(args.end(), {"--symlink", std::filesystem::read_symlink(dir, error).string(), dir});
		} else if (std::filesystem::is_directory(dir, error)) {
			args.insert(args.end(), {"--ro-bind", dir, dir});
		}
	}
	args.insert(args.end(), {"--proc", "/proc", "--dev", "/dev"});
	// Private scratch folders: /tmp, and /dev/shm so that shared memory is no way around its size.
	for (const char* scratch : {"/tmp", "/dev/shm"}) {
		if (scratch_size_) args.insert(args.end(), {"--size", std::to_string(limits_.scratch_bytes)});
		args.insert(args.end(), {"--tmpfs", scratch});
	}
	args.insert(args.end(), {"--chdir", "/tmp", "--clearenv", "--setenv", "HOME", "/tmp", "--setenv", "PATH", "/usr/bin:/bin"});
	if (seccomp_fd >= 0) args.insert(args.end(), {"--seccomp", std::to_string(seccomp_fd)});
	if (program == "/bin/true") {
		args.insert(args.end(), {"--", program});
	} else {
		args.insert(args.end(), {"--ro-bind", program, "/subject", "--", "/subject"});
	}
	return args;
}

std::string seccomp_filter() {
#if defined(__x86_64__)
	const uint32_t DENY = SECCOMP_RET_ERRNO | EPERM;
	std::vector<sock_filter> program{
		BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(seccomp_data, arch)),
		BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, AUDIT_ARCH_X86_64, 1, 0),
		BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_KILL_PROCESS),
		BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(seccomp_data, nr)),
		// The x32 system calls of the same architecture.
		BPF_JUMP(BPF_JMP | BPF_JGE | BPF_K, 0x40000000, 0, 1),
		BPF_STMT(BPF_RET | BPF_K, DENY),
	};
	auto deny = [&](uint32_t call, uint32_t action) {
		program.push_back(BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, call, 0, 1));
		program.push_back(BPF_STMT(BPF_RET | BPF_K, action));
	};
	// memfd_create: memory that no limit counts.
	for (uint32_t call : {SYS_fork, SYS_vfork, SYS_kill, SYS_ptrace, SYS_process_vm_readv, SYS_process_vm_writev,
	                      SYS_socket, SYS_setsid, SYS_memfd_create}) {
		deny(call, DENY);
	}
	// clone3 passes its flags in memory a filter cannot read: ENOSYS makes the C library use clone.
	deny(SYS_clone3, SECCOMP_RET_ERRNO | ENOSYS);
	// clone: threads only (CLONE_THREAD in the flags, the first argument's low word).
	program.push_back(BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, SYS_clone, 0, 3));
	program.push_back(BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(seccomp_data, args[0])));
	program.push_back(BPF_JUMP(BPF_JMP | BPF_JSET | BPF_K, CLONE_THREAD, 1, 0));
	program.push_back(BPF_STMT(BPF_RET | BPF_K, DENY));
	program.push_back(BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ALLOW));
	return std::string(reinterpret_cast<const char*>(program.data()), program.size() * sizeof(sock_filter));
#else
	return "";
#endif
}

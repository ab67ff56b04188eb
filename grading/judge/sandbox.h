#pragma once
// Where and how a subject runs (subject.h): inside bubblewrap, with no network, no view of the
// file system but the system's libraries and the subject program itself (read-only), a private
// scratch folder, its own process-id namespace (every process it starts dies with it), and limits
// on CPU time, memory, file size, open files and processes. Where bubblewrap cannot create its
// namespaces (some containers), the subject runs with the process limits, as another user where the
// judge is root, confined to reading the system by Landlock where the kernel has it (landlock.h),
// and every report says which of these held.
#include <cstdint>
#include <string>
#include <vector>

struct Sandbox_Limits {
	double request_seconds = 30.0;    // wall time to answer one request
	double test_case_seconds = 90.0;  // wall time of all the requests of one test case
	uint64_t cpu_seconds = 90;        // CPU time of one subject (one test case)
	uint64_t memory_bytes = uint64_t(2) << 30;
	uint64_t file_bytes = uint64_t(64) << 20;    // largest file it may write (its output log too)
	uint64_t scratch_bytes = uint64_t(64) << 20; // its private /tmp
	uint64_t open_files = 64;
};

class Sandbox {
public:
	enum class Mode { bubblewrap, process_limits, none };

	// `requested`: "auto" (bubblewrap if it works here, else process limits), "bubblewrap" (an
	// error if it does not work), "process-limits" (as where bubblewrap cannot run), "none" (for
	// --debug: a sanitizer's runtime needs the address space; still a fresh process with the time
	// limits).
	static Sandbox choose(const std::string& requested);

	Mode mode() const {
		return mode_;
	}
	// One line for every report: how subjects run, and why if not in bubblewrap.
	const std::string& notice() const {
		return notice_;
	}
	const Sandbox_Limits& limits() const {
		return limits_;
	}
	// With process limits: whether the kernel confines the subject's files by Landlock (landlock.h).
	bool landlock() const {
		return landlock_;
	}
	Sandbox_Limits& limits() {
		return limits_;
	}

	// The command that starts `program` in the sandbox; `seccomp_fd` is where the child will find
	// the system-call filter (seccomp_filter()).
	std::vector<std::string> command(const std::string& program, int seccomp_fd) const;

private:
	Mode mode_ = Mode::process_limits;
	bool scratch_size_ = true; // bwrap --size (bubblewrap >= 0.7)
	bool landlock_ = false;
	std::string notice_;
	Sandbox_Limits limits_;
};

// The system-call filter every subject runs under (a classic BPF program for seccomp): no new
// processes (threads are allowed), no signals to other processes, no tracing of other processes,
// no sockets, no memfd_create. Empty where the lab has no filter for the machine's architecture.
std::string seccomp_filter();

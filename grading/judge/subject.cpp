#include "subject.h"

#include "landlock.h"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>
#include <thread>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <grp.h>
#include <linux/filter.h>
#include <linux/seccomp.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

using protocol::Kind;

constexpr int SECCOMP_FD = 5; // in the child, for bwrap --seccomp

std::string signal_name(int signal) {
	const char* abbreviation = sigabbrev_np(signal);
	return abbreviation ? std::string("SIG") + abbreviation : "signal " + std::to_string(signal);
}

std::string seconds(double s) {
	std::ostringstream out;
	out << s << " s";
	return out.str();
}

// The child's side of fork(): only system calls from here to exec (the judge may have threads).
[[noreturn]] void become_subject(const std::vector<char*>& argv, const Sandbox& sandbox, int requests, int answers,
                                 int log, int seccomp, const sock_fprog* filter, const Landlock_Rules* files) {
	setsid(); // its own process group, killed whole on a time limit
	int null = open("/dev/null", O_RDONLY | O_CLOEXEC);
	dup2(null, 0);
	dup2(log, 1);
	dup2(log, 2);
	dup2(requests, protocol::REQUEST_FD);
	dup2(answers, protocol::ANSWER_FD);
	if (seccomp >= 0) dup2(seccomp, SECCOMP_FD);
	const Sandbox_Limits& limits = sandbox.limits();
	auto limit = [](int resource, uint64_t soft, uint64_t hard) {
		rlimit r{rlim_t(soft), rlim_t(hard)};
		setrlimit(resource, &r);
	};
	// The CPU limit's hard value a little above the soft one: SIGXCPU at the soft one says "CPU time".
	limit(RLIMIT_CPU, limits.cpu_seconds, limits.cpu_seconds + 5);
	limit(RLIMIT_FSIZE, limits.file_bytes, limits.file_bytes);
	limit(RLIMIT_NOFILE, limits.open_files, limits.open_files);
	limit(RLIMIT_CORE, 0, 0);
	if (sandbox.mode() != Sandbox::Mode::none) limit(RLIMIT_AS, limits.memory_bytes, limits.memory_bytes);
	else limit(RLIMIT_AS, RLIM_INFINITY, RLIM_INFINITY); // not the judge's own: a sanitizer maps terabytes
	prctl(PR_SET_PDEATHSIG, SIGKILL);
	char* const clean_environment[] = {const_cast<char*>("PATH=/usr/bin:/bin"), nullptr};
	if (sandbox.mode() == Sandbox::Mode::process_limits) {
		// Without namespaces: another user where the judge is root, files by Landlock, a clean
		// environment, and the system-call filter installed here.
		if (geteuid() == 0 && (setgroups(0, nullptr) != 0 || setgid(65534) != 0 || setuid(65534) != 0)) _exit(126);
		if (files && !files->apply_to_self()) _exit(126);
		if (chdir("/") != 0) _exit(126); // not the grader's folder
		prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0);
		if (filter && prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, filter) != 0) _exit(126);
	}
	close_range(SECCOMP_FD + 1, ~0u, 0);
	if (sandbox.mode() == Sandbox::Mode::process_limits) execve(argv[0], argv.data(), clean_environment);
	else execv(argv[0], argv.data());
	_exit(127);
}

bool wait_readable(int fd, Subject::Clock::time_point until) {
	for (;;) {
		auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - Subject::Clock::now()).count();
		if (left <= 0) return false;
		pollfd p{fd, POLLIN, 0};
		int n = poll(&p, 1, int(std::min<long long>(left, 1000000)));
		if (n > 0) return true;
		if (n < 0 && errno != EINTR) return true; // let read() report it
	}
}

bool wait_writable(int fd, Subject::Clock::time_point until) {
	for (;;) {
		auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - Subject::Clock::now()).count();
		if (left <= 0) return false;
		pollfd p{fd, POLLOUT, 0};
		int n = poll(&p, 1, int(std::min<long long>(left, 1000000)));
		if (n > 0) return true;
		if (n < 0 && errno != EINTR) return true;
	}
}

} // namespace

Subject::Subject(const std::string& program, const Sandbox& sandbox, Hang_Record& hangs)
	: sandbox(sandbox), deadline(Clock::now()), hangs(hangs) {
	std::signal(SIGPIPE, SIG_IGN); // a subject that is gone is an error on write, not a signal
	int requests[2], answers[2], filter_pipe[2] = {-1, -1};
	if (pipe2(requests, O_CLOEXEC) != 0 || pipe2(answers, O_CLOEXEC) != 0) {
		throw std::runtime_error(std::string("judge: cannot make pipes: ") + std::strerror(errno));
	}
	char log_template[] = "/tmp/lab-subject-log-XXXXXX";
	log = mkostemp(log_template, O_CLOEXEC);
	if (log < 0) throw std::runtime_error(std::string("judge: cannot make a log file: ") + std::strerror(errno));
	unlink(log_template);

	// Above the descriptors the child gets (0 to SECCOMP_FD), so that no dup2 there overwrites one
	// before it is moved.
	for (int* fd : {&requests[0], &requests[1], &answers[0], &answers[1], &log}) {
		int moved = fcntl(*fd, F_DUPFD_CLOEXEC, 10);
		close(*fd);
		*fd = moved;
	}

	std::string filter = seccomp_filter();
	sock_fprog filter_program{uint16_t(filter.size() / sizeof(sock_filter)),
	                          reinterpret_cast<sock_filter*>(filter.data())};
	if (sandbox.mode() == Sandbox::Mode::bubblewrap && !filter.empty()) {
		// bwrap reads the filter from a descriptor; it fits a pipe's buffer.
		if (pipe2(filter_pipe, O_CLOEXEC) != 0 || write(filter_pipe[1], filter.data(), filter.size()) != ssize_t(filter.size())) {
			throw std::runtime_error("judge: cannot pass the system-call filter to bwrap");
		}
		close(filter_pipe[1]);
		int moved = fcntl(filter_pipe[0], F_DUPFD_CLOEXEC, 10);
		close(filter_pipe[0]);
		filter_pipe[0] = moved;
	}
	std::vector<std::string> args = sandbox.command(program, filter_pipe[0] >= 0 ? SECCOMP_FD : -1);
	std::vector<char*> argv;
	for (std::string& arg : args) argv.push_back(arg.data());
	argv.push_back(nullptr);

	// Where bubblewrap cannot run: the subject may read the system and its own program, and write
	// nothing (the descriptors it is given stay open).
	std::optional<Landlock_Rules> files;
	if (sandbox.mode() == Sandbox::Mode::process_limits && sandbox.landlock()) {
		std::vector<std::string> readable = system_files();
		readable.push_back(program);
		files.emplace(readable, std::vector<std::string>{});
	}

	pid = fork();
	if (pid < 0) throw std::runtime_error(std::string("judge: cannot fork: ") + std::strerror(errno));
	if (pid == 0) {
		become_subject(argv, sandbox, requests[0], answers[1], log, filter_pipe[0], filter.empty() ? nullptr : &filter_program,
		               files ? &*files : nullptr);
	}
	close(requests[0]);
	close(answers[1]);
	if (filter_pipe[0] >= 0) close(filter_pipe[0]);
	to_subject = requests[1];
	from_subject = answers[0];
	fcntl(to_subject, F_SETFL, O_NONBLOCK);
	fcntl(from_subject, F_SETFL, O_NONBLOCK);
}

void Subject::begin(Clock::time_point deadline_, const std::string& save_requests_) {
	deadline = deadline_;
	save_requests = save_requests_;
}

Subject::~Subject() {
	stop();
	if (log >= 0) close(log);
}

void Subject::stop() {
	if (to_subject >= 0) close(to_subject), to_subject = -1;
	if (from_subject >= 0) close(from_subject), from_subject = -1;
	if (pid > 0) {
		kill(-pid, SIGKILL);
		kill(pid, SIGKILL);
		waitpid(pid, nullptr, 0);
		pid = -1;
	}
}

void Subject::refuse_after_hangs(Kind kind) const {
	const double limit = sandbox.limits().request_seconds;
	std::string hung;
	for (Kind k : hangs.kinds) hung += (hung.empty() ? "" : ", ") + std::string(protocol::kind_functions(k));
	if (std::find(hangs.kinds.begin(), hangs.kinds.end(), kind) != hangs.kinds.end()) {
		throw Subject_Failure(std::string("Fix ") + protocol::kind_functions(kind) + " first: it did not finish in " +
		                      seconds(limit) + " in an earlier test case, so this one was not run (request " +
		                      protocol::kind_name(kind) + ").");
	}
	if (hangs.seconds >= 2.0 * limit) {
		throw Subject_Failure("Fix " + hung + " first: your code did not finish in " + seconds(limit) +
		                      " in earlier test cases, so the test cases after them are not run (request " +
		                      protocol::kind_name(kind) + ").");
	}
}

std::string Subject::exchange(Kind kind, const std::string& payload, const Questions& questions) {
	if (pid <= 0) throw Subject_Failure("judge: the subject is no longer running");
	refuse_after_hangs(kind);
	uint32_t number = ++sequence;
	// A request, or a reply to a question: the request's header and the payload.
	auto message_of = [&](const std::string& body) {
		wire::Request_Header header;
		header.kind = uint32_t(kind), header.sequence = number;
		return wire::message(header, body);
	};
	std::string message = message_of(payload);
	if (!save_requests.empty()) std::ofstream(save_requests, std::ios::binary | std::ios::app) << message;

	auto request_deadline = std::min(deadline, Clock::now() + std::chrono::duration_cast<Clock::duration>(
	                                                                std::chrono::duration<double>(sandbox.limits().request_seconds)));
	const Clock::time_point asked = Clock::now();
	auto time_is_up = [&]() {
		timed_out = true;
		timeout_kind = request_deadline == deadline ? "test case" : "request";
		if (std::find(hangs.kinds.begin(), hangs.kinds.end(), kind) == hangs.kinds.end()) hangs.kinds.push_back(kind);
		hangs.seconds += std::chrono::duration<double>(Clock::now() - asked).count();
		fail(kind, "did not answer in time");
	};
	auto send = [&](const std::string& bytes) {
		for (size_t sent = 0; sent < bytes.size();) {
			if (!wait_writable(to_subject, request_deadline)) time_is_up();
			ssize_t n = write(to_subject, bytes.data() + sent, bytes.size() - sent);
			if (n < 0 && (errno == EAGAIN || errno == EINTR)) continue;
			if (n <= 0) fail(kind, "stopped reading requests");
			sent += size_t(n);
		}
	};
	send(message);

	// The answer: header, then payload, read straight into place.
	auto receive = [&](char* into, size_t size) {
		for (size_t got = 0; got < size;) {
			if (!wait_readable(from_subject, request_deadline)) time_is_up();
			ssize_t n = read(from_subject, into + got, size - got);
			if (n < 0 && (errno == EAGAIN || errno == EINTR)) continue;
			if (n <= 0) fail(kind, "ended before it answered");
			got += size_t(n);
		}
	};
	uint32_t status;
	uint64_t length;
	for (;;) {
		char header_bytes[wire::Answer_Header::BYTES];
		receive(header_bytes, sizeof header_bytes);
		wire::Answer_Header header = wire::answer_header(header_bytes);
		status = header.status, length = header.length;
		if (header.magic != protocol::MAGIC || status > uint32_t(protocol::Status::QUESTION)) {
			fail(kind, "wrote something that is not an answer to its answer channel");
		}
		if (length > answer_limit(payload.size())) {
			fail(kind, "sent an answer of " + std::to_string(length) + " bytes, more than any answer to this request (" +
			               std::to_string(answer_limit(payload.size())) + " bytes): the subject's answer is too large");
		}
		if (header.kind != uint32_t(kind) || header.sequence != number) fail(kind, "answered out of turn");
		if (protocol::Status(status) != protocol::Status::QUESTION) break;
		// A question (protocol.h): answered before the subject goes on.
		if (!questions) fail(kind, "asked the judge a question, which this request does not allow");
		if (length > protocol::MAX_QUESTION) fail(kind, "asked the judge a question longer than any question");
		std::string question(length, '\0');
		receive(question.data(), question.size());
		std::string reply;
		try {
			reply = questions(question);
		} catch (const wire::Malformed& problem) {
			fail(kind, std::string("asked the judge something that is not a question (") + problem.what() + ")");
		}
		send(message_of(reply));
	}
	// Read in pieces, never allocating more than has arrived: a declared length costs nothing.
	std::string answer;
	const size_t PIECE = size_t(1) << 20;
	while (answer.size() < length) {
		size_t at = answer.size();
		answer.resize(at + std::min<uint64_t>(PIECE, length - at));
		receive(answer.data() + at, answer.size() - at);
	}
	if (protocol::Status(status) == protocol::Status::THREW) {
		std::string what = answer.substr(0, 2000);
		if (what.find("bad_alloc") != std::string::npos) {
			what += " (the memory limit is " + std::to_string(sandbox.limits().memory_bytes >> 20) + " MiB)";
		}
		throw Subject_Failure(std::string("your ") + protocol::kind_functions(kind) + " threw an exception: " + what);
	}
	return answer;
}

void Subject::fail(Kind kind, const std::string& what) {
	std::string reason = end_reason();
	// Running out of CPU time is a hang too: the same request would use it up again.
	if (used_up_cpu && std::find(hangs.kinds.begin(), hangs.kinds.end(), kind) == hangs.kinds.end()) {
		hangs.kinds.push_back(kind);
	}
	std::string output = printed();
	bool sanitizer = output.find("Sanitizer") != std::string::npos || output.find("runtime error:") != std::string::npos;
	if (sanitizer) reason = "the sanitizer stopped it at an error in the code (its report ends below)";
	std::string message = std::string("your code (") + protocol::kind_functions(kind) + ", request " +
	                      protocol::kind_name(kind) + ") " + what + ": " + reason + ".";
	if (!output.empty()) message += "\nThe last lines your code printed:\n" + output;
	if (!save_requests.empty()) {
		message += "\nTo step through it in a debugger: gdb --args <the subject program> --replay " + save_requests +
		           " (./lab grade N --debug prints the command)";
	} else if (!sanitizer && reason.find("killed by") != std::string::npos) {
		message += "\n./lab grade N --debug runs it with sanitizers, which name the file and line of the crash";
	}
	throw Subject_Failure(message);
}

std::string Subject::end_reason() {
	if (pid <= 0) return "it had already ended";
	pid_t child = std::exchange(pid, -1);
	int status = 0;
	pid_t done = 0;
	if (!timed_out) {
		// It closed its answer channel or answered wrongly: give it a moment to end by itself.
		for (int i = 0; i < 100 && (done = waitpid(child, &status, WNOHANG)) == 0; i++) {
			std::this_thread::sleep_for(std::chrono::milliseconds(10));
		}
	}
	bool stopped_by_judge = done != child;
	if (stopped_by_judge) {
		kill(-child, SIGKILL);
		kill(child, SIGKILL);
		waitpid(child, &status, 0);
	}
	const Sandbox_Limits& limits = sandbox.limits();
	if (timed_out) {
		return timeout_kind == "request"
		           ? "it was stopped after " + seconds(limits.request_seconds) + " (the time limit of one request)"
		           : "it was stopped when the test case's time limit of " + seconds(limits.test_case_seconds) + " ran out";
	}
	if (stopped_by_judge) return "it did not end by itself and was stopped";
	int signal = 0;
	if (WIFSIGNALED(status)) signal = WTERMSIG(status);
	// bwrap ends with 128 + the signal that ended the program it ran.
	if (WIFEXITED(status) && sandbox.mode() == Sandbox::Mode::bubblewrap && WEXITSTATUS(status) > 128 &&
	    WEXITSTATUS(status) < 128 + 65) {
		signal = WEXITSTATUS(status) - 128;
	}
	if (signal == SIGXCPU) {
		used_up_cpu = true;
		return "it used up its CPU time limit of " + std::to_string(limits.cpu_seconds) + " s";
	}
	if (signal == SIGXFSZ) return "it wrote more than the file size limit of " + std::to_string(limits.file_bytes >> 20) + " MiB";
	if (signal != 0) return "it was killed by " + signal_name(signal) + (signal == SIGKILL ? " (out of memory?)" : "");
	if (WIFEXITED(status)) {
		return "it ended the program with exit status " + std::to_string(WEXITSTATUS(status)) +
		       " (task functions must return, never call exit())";
	}
	return "it ended";
}

std::string Subject::printed(size_t lines) const {
	if (log < 0) return "";
	off_t size = lseek(log, 0, SEEK_END);
	const off_t TAIL = 4096;
	off_t from = std::max<off_t>(0, size - TAIL);
	std::string text(size_t(size - from), '\0');
	if (pread(log, text.data(), text.size(), from) != ssize_t(text.size())) return "";
	std::vector<std::string> all;
	std::istringstream in(text);
	for (std::string line; std::getline(in, line);) all.push_back(line);
	size_t first = all.size() > lines ? all.size() - lines : 0;
	std::string tail;
	for (size_t i = first; i < all.size(); i++) tail += "  | " + all[i] + "\n";
	if (!tail.empty()) tail.pop_back();
	return tail;
}

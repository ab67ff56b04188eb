#include "child_process.h"

#include <chrono>
#include <condition_variable>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <mutex>
#include <poll.h>
#include <stdexcept>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace {
void close_fd(int& fd) {
	if (fd >= 0) ::close(fd);
	fd = -1;
}
} // namespace

Child_Process::Child_Process(const std::vector<std::string>& argv, bool merge_stderr) {
	if (argv.empty()) throw std::invalid_argument("Child_Process: no program");
	int out_pipe[2], err_pipe[2] = {-1, -1};
	if (::pipe2(out_pipe, O_CLOEXEC) != 0 || (!merge_stderr && ::pipe2(err_pipe, O_CLOEXEC) != 0)) {
		throw std::runtime_error(std::string("cannot make a pipe: ") + std::strerror(errno));
	}
	std::vector<char*> args;
	for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
	args.push_back(nullptr);
	pid = ::fork();
	if (pid < 0) throw std::runtime_error(std::string("cannot start ") + argv[0] + ": " + std::strerror(errno));
	if (pid == 0) {
		::setpgid(0, 0);
		::dup2(out_pipe[1], STDOUT_FILENO);
		::dup2(merge_stderr ? out_pipe[1] : err_pipe[1], STDERR_FILENO);
		int null = ::open("/dev/null", O_RDONLY);
		if (null >= 0) ::dup2(null, STDIN_FILENO);
		::signal(SIGPIPE, SIG_DFL);
		::execvp(args[0], args.data());
		std::string message = std::string("cannot run ") + argv[0] + ": " + std::strerror(errno) + "\n";
		(void)!::write(STDERR_FILENO, message.data(), message.size());
		::_exit(127);
	}
	::setpgid(pid, pid); // (also in the child: whichever runs first)
	::close(out_pipe[1]);
	output = out_pipe[0];
	if (!merge_stderr) {
		::close(err_pipe[1]);
		error = err_pipe[0];
	}
}

Child_Process::~Child_Process() {
	kill();
	wait();
	close_fd(output);
	close_fd(error);
}

void Child_Process::pause() {
	if (!reaped) ::kill(-pid, SIGSTOP);
}

void Child_Process::resume() {
	if (!reaped) ::kill(-pid, SIGCONT);
}

void Child_Process::kill() {
	if (!reaped) {
		::kill(-pid, SIGKILL);
		::kill(-pid, SIGCONT);
	}
}

int Child_Process::wait() {
	if (reaped) return status;
	int raw = 0;
	while (::waitpid(pid, &raw, 0) < 0 && errno == EINTR) {
	}
	reaped = true;
	status = WIFEXITED(raw) ? WEXITSTATUS(raw) : WIFSIGNALED(raw) ? 128 + WTERMSIG(raw) : 1;
	return status;
}

std::string read_all(int fd) {
	std::string text;
	char buffer[65536];
	for (;;) {
		ssize_t n = ::read(fd, buffer, sizeof buffer);
		if (n < 0 && errno == EINTR) continue;
		if (n <= 0) break;
		text.append(buffer, size_t(n));
	}
	return text;
}

int run_program(const std::vector<std::string>& argv, std::string& out, std::string& err, double seconds) {
	Child_Process child(argv, false);
	// A watch that stops the program at its time limit: its pipes then close and the reads end.
	std::mutex mutex;
	std::condition_variable finished;
	bool done = false;
	std::thread watch;
	if (seconds > 0) {
		watch = std::thread([&] {
			std::unique_lock<std::mutex> lock(mutex);
			if (!finished.wait_for(lock, std::chrono::duration<double>(seconds), [&] { return done; })) child.kill();
		});
	}
	// Both pipes at once, or a program that fills one while the other is read would wait forever.
	std::thread error_reader([&] { err = read_all(child.error_fd()); });
	out = read_all(child.output_fd());
	error_reader.join();
	if (watch.joinable()) {
		{
			std::lock_guard<std::mutex> lock(mutex);
			done = true;
		}
		finished.notify_one();
		watch.join();
	}
	return child.wait();
}

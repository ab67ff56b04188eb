#pragma once
// A program the viewer runs: a renderer, a build, a grader. Started with fork and exec (no
// shell, so no argument is ever interpreted), in a process group of its own, so that stopping it
// stops whatever it started (a build's compilers, a grader's subjects).
#include <string>
#include <vector>

class Child_Process {
public:
	// Starts argv[0] (a path, or a name looked up in PATH) with argv. Its standard output comes back
	// through output_fd(); its standard error goes to the same pipe when `merge_stderr`, else to a
	// pipe read by error_fd(). Throws std::runtime_error if it cannot start.
	Child_Process(const std::vector<std::string>& argv, bool merge_stderr);
	~Child_Process(); // kills it, if it still runs, and reaps it
	Child_Process(const Child_Process&) = delete;
	Child_Process& operator=(const Child_Process&) = delete;

	int output_fd() const {
		return output;
	}
	int error_fd() const {
		return error;
	}

	void pause();  // SIGSTOP to its group
	void resume(); // SIGCONT
	void kill();   // SIGKILL to its group
	// Waits for it to end: its exit status, or 128 + the signal that ended it.
	int wait();

private:
	int pid = -1;
	int output = -1, error = -1;
	bool reaped = false;
	int status = 0;
};

// Reads a file descriptor to its end.
std::string read_all(int fd);

// Runs a program to its end and returns its exit status, with its standard output in `out` and its
// standard error in `err`. With `seconds` > 0 it is stopped (SIGKILL, status 137) when it runs longer.
int run_program(const std::vector<std::string>& argv, std::string& out, std::string& err, double seconds = 0);

// The student's loop in the viewer: the watch on student/, the rebuild after an edit, and a task's
// grader run from the page (Viewer_Session, viewer_session.h).
#include "diagnostics.h"
#include "viewer_session.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>

namespace fs = std::filesystem;

namespace {
double seconds_since(std::chrono::steady_clock::time_point start) {
	return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Each regular file's modification time and size: what an edit changes.
std::map<std::string, std::pair<int64_t, int64_t>> file_stamps(const std::string& dir) {
	std::map<std::string, std::pair<int64_t, int64_t>> stamps;
	std::error_code error;
	for (const auto& entry : fs::directory_iterator(dir, error)) {
		struct stat info {};
		if (::stat(entry.path().c_str(), &info) != 0 || !S_ISREG(info.st_mode)) continue;
		int64_t nanoseconds = int64_t(info.st_mtim.tv_sec) * 1000000000 + info.st_mtim.tv_nsec;
		stamps[entry.path().filename().string()] = {nanoseconds, int64_t(info.st_size)};
	}
	return stamps;
}

} // namespace

void Viewer_Session::rebuild_student() {
	std::lock_guard<std::mutex> one_build(build_mutex);
	if (stopping) return;
	{
		std::lock_guard<std::mutex> lock(mutex);
		build_state = "building";
	}
	hub.publish("build", nlohmann::json{{"state", "building"}}.dump());
	// A running program's file cannot be replaced: the student's renderer stops for the build.
	stop_side(Side::student).reset();
	auto start = std::chrono::steady_clock::now();
	std::string log;
	int status = run_lines(config.rebuild_command, [&](const std::string& line) { log += line + "\n"; });
	nlohmann::json diagnostics = nlohmann::json::array();
	for (const Diagnostic& d : parse_diagnostics(log)) {
		diagnostics.push_back({{"file", d.file}, {"line", d.line}, {"column", d.column}, {"severity", d.severity},
		                       {"message", d.message}});
	}
	std::string state = status == 0 ? "ok" : "failed";
	{
		std::lock_guard<std::mutex> lock(mutex);
		build_state = state;
		if (status != 0) {
			student.state = "build failed";
			student.frame.reset();
			comparison.reset();
		}
	}
	hub.publish("build", nlohmann::json{{"state", state},
	                                    {"status", status},
	                                    {"seconds", seconds_since(start)},
	                                    {"diagnostics", diagnostics},
	                                    {"log", last_lines(log, 60)}}
	                         .dump());
	if (status == 0 && !stopping) {
		start_side(Side::student);
		match_reference_estimator(); // the edit may have finished (or undone) task 6's light sampling
	}
}

void Viewer_Session::watch_student_files() {
	using namespace std::chrono_literals;
	auto stamps = file_stamps(config.student_dir);
	while (!stopping) {
		std::this_thread::sleep_for(200ms);
		auto now = file_stamps(config.student_dir);
		if (now == stamps) continue;
		// An editor may write a file in several steps: build once it has settled.
		do {
			stamps = now;
			std::this_thread::sleep_for(100ms);
			now = file_stamps(config.student_dir);
		} while (now != stamps && !stopping);
		if (!stopping && !config.rebuild_command.empty()) rebuild_student();
	}
}

void Viewer_Session::grade(int task) {
	if (task < 1 || task > 8) throw Request_Error(400, "task: expected a task number from 1 to 8, got " + std::to_string(task));
	if (config.grade_command.empty()) throw Request_Error(404, "this viewer runs no grader");
	{
		std::lock_guard<std::mutex> lock(mutex);
		if (grading) throw Request_Error(409, "the grader of task " + std::to_string(grading) + " is still running");
		grading = task;
	}
	if (grader.joinable()) grader.join(); // the previous one has finished
	grader = std::thread([this, task] {
		std::vector<std::string> args = config.grade_command;
		args.push_back(std::to_string(task));
		hub.publish("grade", nlohmann::json{{"task", task}, {"started", true}}.dump());
		int status = run_lines(args, [&](const std::string& line) {
			hub.publish("grade", nlohmann::json{{"task", task}, {"line", line}}.dump());
		});
		{
			std::lock_guard<std::mutex> lock(mutex);
			grading = 0;
		}
		hub.publish("graded", nlohmann::json{{"task", task}, {"status", status}}.dump());
	});
}

int Viewer_Session::run_lines(const std::vector<std::string>& argv,
                              const std::function<void(const std::string&)>& line) {
	try {
		Child_Process child(argv, true);
		{
			std::lock_guard<std::mutex> lock(mutex);
			running.push_back(&child);
		}
		if (stopping) child.kill();
		std::string pending;
		char buffer[4096];
		for (;;) {
			ssize_t n = ::read(child.output_fd(), buffer, sizeof buffer);
			if (n < 0 && errno == EINTR) continue;
			if (n <= 0) break;
			pending.append(buffer, size_t(n));
			for (size_t eol; (eol = pending.find('\n')) != std::string::npos; pending.erase(0, eol + 1)) {
				line(pending.substr(0, eol));
			}
		}
		if (!pending.empty()) line(pending);
		int status = child.wait();
		std::lock_guard<std::mutex> lock(mutex);
		running.erase(std::find(running.begin(), running.end(), &child));
		return status;
	} catch (const std::exception& e) {
		line(e.what());
		return 1;
	}
}


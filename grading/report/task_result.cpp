#include "task_result.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstring>
#include <deque>
#include <fstream>

namespace fs = std::filesystem;
using Json = nlohmann::json;

const std::vector<Task_Info>& lab_tasks() {
	static const std::vector<Task_Info> tasks{
		{1, "camera rays", "student/task1_camera.cpp", "handouts/task1_camera.md"},
		{2, "intersections", "student/task2_shapes.cpp", "handouts/task2_shapes.md"},
		{3, "BVH", "student/task3_bvh.cpp", "handouts/task3_bvh.md"},
		{4, "path tracing", "student/task4_path.cpp", "handouts/task4_path.md"},
		{5, "materials", "student/task5_materials.cpp", "handouts/task5_materials.md"},
		{6, "direct lighting", "student/task6_direct_lighting.cpp", "handouts/task6_direct_lighting.md"},
		{7, "environment light", "student/task7_env_light.cpp", "handouts/task7_env_light.md"},
		{8, "adaptive sampling (optional)", "student/task8_adaptive.cpp", "handouts/task8_adaptive.md"},
	};
	return tasks;
}

std::string status_name(Status status) {
	switch (status) {
	case Status::pass: return "PASS";
	case Status::fail: return "FAIL";
	case Status::crashed: return "CRASHED";
	case Status::not_run: return "NOT RUN";
	}
	return "";
}

size_t Task_Result::passed_count() const {
	return size_t(std::count_if(test_cases.begin(), test_cases.end(), [](const Test_Case& c) { return c.passed; }));
}

namespace {

constexpr int TIMEOUT_STATUS = 124; // what `timeout` returns when it stopped the grader
constexpr size_t LOG_TAIL_LINES = 40;

std::string last_lines(const fs::path& file, size_t count) {
	std::ifstream in(file);
	std::deque<std::string> lines;
	for (std::string line; std::getline(in, line);) {
		lines.push_back(line);
		if (lines.size() > count) lines.pop_front();
	}
	std::string text;
	for (const std::string& line : lines) text += line + "\n";
	return text;
}

// `count` lines of a build log from its first error (the one to fix first; a linker's error names an
// undefined reference first), or its last lines.
std::string lines_from_first_error(const fs::path& file, size_t count) {
	std::ifstream in(file);
	std::vector<std::string> lines;
	for (std::string line; std::getline(in, line);) lines.push_back(line);
	size_t first = lines.size() - std::min(count, lines.size());
	for (size_t i = 0; i < lines.size(); i++) {
		if (lines[i].find("error") != std::string::npos || lines[i].find("undefined reference") != std::string::npos) {
			first = i;
			break;
		}
	}
	std::string text;
	for (size_t i = first; i < std::min(lines.size(), first + count); i++) text += lines[i] + "\n";
	return text;
}

std::string where(const Json& record) {
	return record.value("file", "?") + ":" + std::to_string(record.value("line", 0));
}

Failure read_failure(const Json& record) {
	return Failure{record.value("kind", "check"), where(record), record.value("expression", ""),
	               record.value("expansion", ""), record.value("messages", std::vector<std::string>{})};
}

Image_Test read_image_test(const fs::path& dir, const Json& record) {
	Image_Test test;
	test.scene = record.value("scene", "");
	test.render = dir / record.value("render", "");
	test.reference = dir / record.value("reference", "");
	test.z_map = dir / record.value("z_map", "");
	test.pass = record.value("pass", false);
	test.message = record.value("message", "");
	test.z_critical = record["z_critical"].is_number() ? record["z_critical"].get<double>() : 0.0;
	return test;
}

Test_Case read_test_case(const fs::path& dir, const Json& record) {
	Test_Case test_case{record.value("id", ""), record.value("name", "?"), where(record), record.value("passed", false),
	                    {}, record.value("more_failures", size_t(0)), {}, {}};
	for (const Json& failure : record.value("failures", Json::array())) {
		test_case.failures.push_back(read_failure(failure));
	}
	for (const Json& item : record.value("attachments", Json::array())) {
		if (item.value("type", "") == "image_test") test_case.image_tests.push_back(read_image_test(dir, item));
		if (item.value("type", "") != "figures") continue;
		for (const Json& figure : item.value("figures", Json::array())) {
			test_case.figures.push_back(Figure{dir / figure.value("file", ""), figure.value("caption", "")});
		}
	}
	return test_case;
}

// The test case the grader was in when it stopped: the one still running, or the one in which
// Catch2 caught the fatal signal.
std::string interrupted_test_case(const Task_Result& result) {
	if (!result.running.empty()) return result.running;
	for (const Test_Case& test_case : result.test_cases) {
		for (const Failure& failure : test_case.failures) {
			if (failure.kind == "crash") return test_case.name;
		}
	}
	return "";
}

// How the grader ended. Catch2's exit status is the number of failed checks (at most 255), so it
// cannot tell a crash from many failures: the record does. Catch2 catches fatal signals, records
// them (fatal_error) and ends the run; a grader killed outright leaves its record unfinished.
void judge(Task_Result& result, int exit_status, const Json& record) {
	bool finished = record.value("finished", false);
	std::string fatal_error = record.contains("fatal_error") && record["fatal_error"].is_string()
	                              ? record["fatal_error"].get<std::string>()
	                              : "";
	bool timed_out = exit_status == TIMEOUT_STATUS && (!finished || fatal_error.rfind("SIGTERM", 0) == 0);
	size_t failed = result.test_cases.size() - result.passed_count();
	std::string in = interrupted_test_case(result);
	in = in.empty() ? "" : " in the test case \"" + in + "\"";
	std::string look = " Its output ends below; run `./lab grade " + std::to_string(result.task.number) +
	                   "` to see it all.";
	result.status = Status::crashed;
	if (timed_out) {
		result.why = "The grader did not finish in time and was stopped" + in +
		             ": look for an endless loop or a very slow function." + look;
	} else if (!fatal_error.empty()) {
		result.why = "The grader crashed (" + fatal_error + ")" + in + "." + look;
	} else if (!finished) {
		int signal = exit_status - 128;
		std::string how = signal > 0 ? "signal " + std::to_string(signal) + ": " + strsignal(signal)
		                             : "exit status " + std::to_string(exit_status);
		result.why = "The grader stopped before its summary (" + how + ")" + in + "." + look;
	} else if (result.test_cases.empty()) {
		result.why = "The grader ran no test case." + look;
	} else if (!result.not_run.empty()) {
		result.why = std::to_string(result.not_run.size()) + " of the grader's test cases did not run (\"" +
		             result.not_run.front() + "\" first): a task passes only when every test case ran and passed." + look;
	} else if (failed > 0) {
		result.status = Status::fail;
		result.why = std::to_string(failed) + " of " + std::to_string(result.test_cases.size()) +
		             " test cases fail.";
	} else if (exit_status != 0) {
		result.why = "Every test case passed, but the grader exited with status " + std::to_string(exit_status) +
		             "." + look;
	} else {
		result.status = Status::pass;
		result.why = "All " + std::to_string(result.test_cases.size()) + " test cases pass.";
	}
}

// The judge's list of its test cases: {"id": ..., "name": ...} each.
std::vector<Listed_Test_Case> read_listed_test_cases(const Json& list) {
	std::vector<Listed_Test_Case> listed;
	for (const Json& item : list) {
		if (item.is_object()) listed.push_back({item.value("id", ""), item.value("name", "?")});
	}
	return listed;
}

Json read_record(const fs::path& file) {
	std::ifstream in(file);
	if (!in) return Json::object();
	Json record = Json::parse(in, nullptr, false);
	return record.is_object() ? record : Json::object();
}

} // namespace

Task_Result read_task_result(const fs::path& dir, const Task_Info& task) {
	std::string name = "task" + std::to_string(task.number);
	Task_Result result;
	result.task = task;
	std::ifstream exit_file(dir / (name + ".exit"));
	int exit_status = 0;
	if (!(exit_file >> exit_status)) {
		result.status = Status::not_run;
		result.why = "The grader was not run.";
		if (fs::exists(dir / (name + ".build.log"))) { // left only when the build failed
			result.why = "The grader did not build: the compiler's first error is below.";
			result.log_file = name + ".build.log";
			result.log_tail = lines_from_first_error(dir / result.log_file, LOG_TAIL_LINES);
		}
		return result;
	}
	Json record = read_record(dir / (name + ".json"));
	for (const Json& test_case : record.value("test_cases", Json::array())) {
		result.test_cases.push_back(read_test_case(dir, test_case));
	}
	if (record.contains("running") && record["running"].is_object()) {
		result.running = record["running"].value("name", "");
	}
	result.sandbox = record.value("sandbox", "");
	result.inputs = record.value("inputs", "");
	result.expected = read_listed_test_cases(record.value("expected_test_cases", Json::array()));
	for (const Listed_Test_Case& listed : result.expected) {
		bool ran = std::any_of(result.test_cases.begin(), result.test_cases.end(),
		                       [&](const Test_Case& c) { return c.name == listed.name; });
		if (!ran) result.not_run.push_back(listed.name);
	}
	if (!record.contains("expected_test_cases")) result.not_run.push_back("(the judge recorded no list of test cases)");
	result.log_file = name + ".log";
	judge(result, exit_status, record);
	if (result.status == Status::crashed) result.log_tail = last_lines(dir / result.log_file, LOG_TAIL_LINES);
	return result;
}

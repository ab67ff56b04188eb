#include "security_grading.h"

#include "lab_catch2.h"
#include <nlohmann/json.hpp>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iterator>

namespace fs = std::filesystem;

const std::map<int, std::string> TASK_FILES{
	{1, "task1_camera.cpp"},    {2, "task2_shapes.cpp"},          {3, "task3_bvh.cpp"},      {4, "task4_path.cpp"},
	{5, "task5_materials.cpp"}, {6, "task6_direct_lighting.cpp"}, {7, "task7_env_light.cpp"}, {8, "task8_adaptive.cpp"}};

std::string read_file(const fs::path& path) {
	std::ifstream in(path, std::ios::binary);
	return std::string(std::istreambuf_iterator<char>(in), {});
}

// A value of the grading kit (build/grading/kit.env: NAME='value' lines).
std::string kit_value(const std::string& name) {
	const char* kit = std::getenv("LAB_KIT");
	REQUIRE(kit != nullptr);
	std::ifstream in(kit);
	for (std::string line; std::getline(in, line);) {
		if (line.rfind(name + "='", 0) == 0 && line.size() > name.size() + 3) {
			return line.substr(name.size() + 2, line.size() - name.size() - 3);
		}
	}
	FAIL("grading/kit.env has no " << name);
	return "";
}

// The text of hostile file `name` with its @NAME@ placeholders replaced.
std::string hostile_source(const std::string& name, const fs::path& out,
                           const std::map<std::string, std::string>& placeholders) {
	std::string source = read_file("tests/security/hostile/" + name);
	REQUIRE_FALSE(source.empty());
	std::map<std::string, std::string> all = placeholders;
	all.emplace("@CORRECT_TASK1_IF@", read_file("tests/security/hostile/correct_task1_if.inc"));
	all.emplace("@ROOT@", fs::current_path().string());
	all.emplace("@OUT@", out.string());
	for (const auto& [key, value] : all) {
		for (size_t at = 0; (at = source.find(key, at)) != std::string::npos; at += value.size()) {
			source.replace(at, key.size(), value);
		}
	}
	return source;
}

namespace {

// Runs `command` with /bin/sh: its exit status, and the largest resident set (KiB) of any process
// of the command.
int run(const std::string& command, long& largest_kib) {
	pid_t child = fork();
	if (child == 0) {
		execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
		_exit(127);
	}
	int status = 0;
	rusage usage{};
	wait4(child, &status, 0, &usage);
	largest_kib = usage.ru_maxrss;
	return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

} // namespace

// Grades a fresh submission of the given task files (task number -> text) in `dir` with the grading
// kit, as ./lab grade-submission does, and returns the result of each task it graded.
std::map<int, Grade> grade_files(const Temp_Dir& dir, const std::map<int, std::string>& files,
                                 const std::string& options) {
	fs::path submission = dir.path() / "submission", out = dir.path() / "out";
	fs::create_directories(submission);
	for (const auto& [task, text] : files) std::ofstream(submission / TASK_FILES.at(task)) << text;
	const char* kit = std::getenv("LAB_KIT");
	REQUIRE(kit != nullptr);
	// LAB_SANDBOX=process-limits (the suite's other modes): grade as where bubblewrap cannot run.
	std::string allow = std::getenv("LAB_SANDBOX") ? " --allow-unsandboxed" : "";
	std::string command = "KIT='" + std::string(kit) + "' grading/bin/grade-submission '" + submission.string() +
	                      "' --out '" + out.string() + "' " + options + allow + " > '" + dir.file("grading.log") +
	                      "' 2>&1";
	long largest_kib = 0;
	auto started = std::chrono::steady_clock::now();
	int status = run(command, largest_kib);
	double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
	INFO(read_file(dir.file("grading.log")));
	REQUIRE(status == 0);

	// Each task's points: the rubric's for its test cases ("Task N: ..." in Gradescope's results.json).
	std::map<int, double> points;
	if (fs::exists(out / "results.json")) {
		nlohmann::json results = nlohmann::json::parse(read_file(out / "results.json"));
		for (const auto& test : results.at("tests")) {
			std::string name = test.at("name").get<std::string>();
			if (name.rfind("Task ", 0) == 0) points[name[5] - '0'] += test.at("score").get<double>();
		}
	}
	std::map<int, Grade> grades;
	for (const auto& [task, file] : TASK_FILES) {
		std::string name = "task" + std::to_string(task);
		bool not_built = fs::exists(out / (name + ".build.log"));
		if (!not_built && !fs::exists(out / (name + ".json"))) continue; // not graded
		Grade& grade = grades[task];
		grade.points = std::max(0.0, points[task]); // failed requirements' penalties never go below 0 (rubric.h)
		grade.largest_process_kib = largest_kib;
		grade.seconds = seconds;
		grade.report = read_file(out / "index.html");
		if (not_built) {
			grade.messages = read_file(out / (name + ".build.log"));
			continue;
		}
		grade.built = true;
		nlohmann::json record = nlohmann::json::parse(read_file(out / (name + ".json")));
		for (const auto& test_case : record.at("test_cases")) {
			grade.test_cases++;
			grade.passed += test_case.at("passed").get<bool>();
			std::string name = test_case.at("name").get<std::string>();
			(test_case.at("passed").get<bool>() ? grade.passed_names : grade.failed).push_back(name);
			for (const auto& failure : test_case.at("failures")) {
				grade.messages += failure.value("expansion", "") + "\n";
				for (const auto& message : failure.at("messages")) grade.messages += message.get<std::string>() + "\n";
			}
		}
		// The judge ran every one of its test cases.
		CHECK(grade.test_cases == record.at("expected_test_cases").size());
	}
	return grades;
}

// Grades `hostile` (with @NAME@ placeholders replaced) as the task's file of a fresh submission.
Grade grade(const std::string& hostile, int task, const std::map<std::string, std::string>& placeholders,
            const std::string& options) {
	Temp_Dir dir;
	std::string source = hostile_source(hostile, dir.path() / "out", placeholders);
	std::map<int, Grade> grades = grade_files(dir, {{task, source}}, "--tasks " + std::to_string(task) + " " + options);
	REQUIRE(grades.count(task) == 1);
	return grades[task];
}

// The hostile file earned nothing: it did not build, or every test case of its task failed; and
// the report shows why.
void require_nothing_earned(const Grade& grade, const std::string& reason) {
	INFO("the judge's messages:\n" << grade.messages.substr(0, 3000));
	if (grade.built) {
		CHECK(grade.test_cases > 0);
		CHECK(grade.passed == 0);
	}
	CHECK_THAT(grade.messages, contains_text(reason));
	CHECK_THAT(grade.report, contains_text(reason));
}


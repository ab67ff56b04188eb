#pragma once
// Grading hostile files as an instructor grades a submission (grading/bin/grade-submission with the
// grading kit: sandboxed compile, subject in the sandbox LAB_SANDBOX chooses, verdicts by the
// judge), for the security suite (test_security.cpp, test_reference_holder.cpp). Run from the
// repository root with LAB_KIT naming the grading kit (build/grading/kit.env).
#include "temp_dir.h"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

extern const std::map<int, std::string> TASK_FILES; // task number -> file name, as in student/

std::string read_file(const std::filesystem::path& path);

// A value of the grading kit (build/grading/kit.env: NAME='value' lines).
std::string kit_value(const std::string& name);

struct Grade {
	bool built = false;           // the file compiled and linked
	size_t test_cases = 0, passed = 0;
	double points = 0.0;          // what the rubric gives for them (results.json)
	std::vector<std::string> failed; // the names of the test cases that failed
	std::vector<std::string> passed_names;
	std::string messages;         // every failure message the judge recorded, or the build log
	std::string report;           // the HTML page
	long largest_process_kib = 0; // the largest resident set of any process of the grading
	double seconds = 0.0;         // the grading's wall time
};

// The text of hostile file `name` (tests/security/hostile/) with its @NAME@ placeholders replaced:
// @CORRECT_TASK1_IF@, @ROOT@ (the repository), @OUT@ (`out`, the grading's output folder) and those
// given.
std::string hostile_source(const std::string& name, const std::filesystem::path& out,
                           const std::map<std::string, std::string>& placeholders = {});

// Grades a fresh submission of the given task files (task number -> text) in `dir` with the grading
// kit, as ./lab grade-submission does (output folder dir/out), and returns the result of each task
// it graded. Without --tasks in `options` all eight are graded, in order, into that one folder: as
// Gradescope grades.
std::map<int, Grade> grade_files(const Temp_Dir& dir, const std::map<int, std::string>& files,
                                 const std::string& options);

// Grades `hostile` (with @NAME@ placeholders replaced) as the task's file of a fresh submission,
// that task alone.
Grade grade(const std::string& hostile, int task, const std::map<std::string, std::string>& placeholders = {},
            const std::string& options = "");

// The hostile file earned nothing: it did not build, or every test case of its task failed; and
// the report shows why.
void require_nothing_earned(const Grade& grade, const std::string& reason);

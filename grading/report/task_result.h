#pragma once
// One task's result, read from the files `./lab report` leaves in the report directory:
//
//   task<N>.build.log   the output of building grader_task<N>_student
//   task<N>.exit        the grader's exit status (absent: the grader did not build, or was not run)
//   task<N>.log         the grader's output (stdout and stderr)
//   task<N>.json        what the grader's judge recorded (grading/report/report_listener.cpp): the
//                       judge's test cases (each with its id and title), each one's result, how the
//                       student's code ran
//   task<N>_*.png       the images of its reference-image test (tests/support/graded_images.cpp)
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

struct Task_Info {
	int number;
	std::string title;        // as in the README's table
	std::string student_file; // what the student edits
	std::string handout;
};
const std::vector<Task_Info>& lab_tasks();

enum class Status { pass, fail, crashed, not_run };
std::string status_name(Status status); // PASS, FAIL, CRASHED, NOT RUN

struct Failure {
	std::string kind;       // check, failure, unexpected exception, crash, ...
	std::string where;      // file:line
	std::string expression; // e.g. CHECK( ok ), may be empty
	std::string expansion;  // the expression with values, may be empty
	std::vector<std::string> messages;
};

struct Image_Test {
	std::string scene;
	std::filesystem::path render, reference, z_map;
	bool pass = false;
	std::string message;
	double z_critical = 0.0;
};

// A picture a test case shows (an attachment of type "figures"), e.g. task 8's rate maps.
struct Figure {
	std::filesystem::path file;
	std::string caption;
};

struct Test_Case {
	std::string id;          // the judge's tag [id:ID], which the rubric grades by; "" if it has none
	std::string name, where; // name: the TEST_CASE's title
	bool passed = false;
	std::vector<Failure> failures;
	size_t more_failures = 0; // failed checks beyond those recorded
	std::vector<Image_Test> image_tests;
	std::vector<Figure> figures;
};

// A test case as the judge lists them all, whether it ran or not.
struct Listed_Test_Case {
	std::string id, name;
};

struct Task_Result {
	Task_Info task;
	Status status = Status::not_run;
	std::string why; // one sentence on the status
	std::vector<Test_Case> test_cases;
	std::string running;  // the test case in progress when the grader stopped, if any
	std::string log_file; // the file next to the report that tells more (grader output or build log)
	std::string log_tail; // its last lines, shown when the grader crashed or did not build
	std::string sandbox;  // how the judge ran the student's code (grading/judge/sandbox.h)
	std::string inputs;   // the public test cases, or drawn from a grading seed
	std::vector<Listed_Test_Case> expected; // every test case of the judge, as it listed them
	std::vector<std::string> not_run;       // the names of those that have no result

	size_t passed_count() const;
};

Task_Result read_task_result(const std::filesystem::path& dir, const Task_Info& task);

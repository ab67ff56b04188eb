// The grade report's pieces (label report): what a task's status is, given the files ./lab report
// leaves (task_result.h), the HTML helpers, and the heat map's colour scale.
#include "html.h"
#include "task_result.h"
#include "temp_dir.h"
#include "z_heat_map.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>

namespace {

// A record as the listener writes it: one test case per entry of `passed`, and the judge's list of
// the test cases it has (`expected`, by default those that ran).
std::string record(bool finished, std::initializer_list<bool> passed, const std::string& fatal_error = "",
                   int expected = -1) {
	std::string cases, names;
	int i = 0;
	for (bool p : passed) {
		cases += std::string(cases.empty() ? "" : ",") + R"({"name": "case )" + std::to_string(i++) +
		         R"(", "file": "tests/task1/x.cpp", "line": 3, "passed": )" + (p ? "true" : "false") +
		         R"(, "failures": [], "more_failures": 0, "attachments": []})";
	}
	for (int n = 0; n < (expected < 0 ? i : expected); n++) {
		names += std::string(names.empty() ? "" : ",") + "\"case " + std::to_string(n) + "\"";
	}
	std::string fatal = fatal_error.empty() ? "null" : "\"" + fatal_error + "\"";
	return R"({"grader": "judge_task1", "finished": )" + std::string(finished ? "true" : "false") +
	       R"(, "fatal_error": )" + fatal + R"(, "running": null, "expected_test_cases": [)" + names +
	       R"(], "test_cases": [)" + cases + "]}";
}

// Task 1's status from its files: exit status (none: not written) and record (empty: none).
Task_Result task1(const Temp_Dir& dir, const std::string& exit_status, const std::string& json) {
	if (!exit_status.empty()) std::ofstream(dir.file("task1.exit")) << exit_status << "\n";
	if (!json.empty()) std::ofstream(dir.file("task1.json")) << json;
	std::ofstream(dir.file("task1.log")) << "the grader's output\n";
	return read_task_result(dir.path(), lab_tasks().at(0));
}

} // namespace

TEST_CASE("report: a grader that ran to its summary is PASS when every test case passed, else FAIL") {
	Temp_Dir pass, fail;
	CHECK(task1(pass, "0", record(true, {true, true})).status == Status::pass);
	Task_Result failed = task1(fail, "3", record(true, {true, false}));
	CHECK(failed.status == Status::fail);
	CHECK(failed.passed_count() == 1);
}

TEST_CASE("report: a judge whose test cases did not all run is not PASS, even if those that ran passed") {
	Temp_Dir missing, unlisted;
	Task_Result some = task1(missing, "0", record(true, {true, true}, "", 3));
	CHECK(some.status != Status::pass);
	CHECK_THAT(some.why, Catch::Contains("case 2"));
	std::string without_list = record(true, {true});
	without_list.erase(without_list.find(R"("expected_test_cases")"), std::string(R"("expected_test_cases": ["case 0"], )").size());
	CHECK(task1(unlisted, "0", without_list).status != Status::pass);
}

TEST_CASE("report: Catch2's exit status counts failed checks, so a status above 128 is not a crash by itself") {
	Temp_Dir dir;
	CHECK(task1(dir, "255", record(true, {false})).status == Status::fail);
}

TEST_CASE("report: a crash, a time-out or a missing summary is CRASHED and shows the grader's output") {
	Temp_Dir segfault, timeout, killed, no_record;
	Task_Result crashed = task1(segfault, "139", record(true, {false}, "SIGSEGV - Segmentation violation signal"));
	CHECK(crashed.status == Status::crashed);
	CHECK_THAT(crashed.why, Catch::Contains("SIGSEGV"));
	CHECK(crashed.log_tail == "the grader's output\n");
	Task_Result timed_out = task1(timeout, "124", record(true, {false}, "SIGTERM - Termination request signal"));
	CHECK(timed_out.status == Status::crashed);
	CHECK_THAT(timed_out.why, Catch::Contains("did not finish in time"));
	CHECK(task1(killed, "137", record(false, {true})).status == Status::crashed);
	CHECK(task1(no_record, "1", "").status == Status::crashed);
}

TEST_CASE("report: a grader that did not build is NOT RUN and shows the compiler's first error") {
	Temp_Dir dir;
	std::ofstream(dir.file("task1.build.log")) << "[1/2] Building\nstudent/task1_camera.cpp:3:1: error: oops\nmore\n";
	Task_Result result = task1(dir, "", "");
	CHECK(result.status == Status::not_run);
	CHECK(result.log_tail == "student/task1_camera.cpp:3:1: error: oops\nmore\n");
}

TEST_CASE("report: HTML text is escaped and images are base64 (RFC 4648 test vectors)") {
	CHECK(escape("a < b && c > \"d\" 'e'") == "a &lt; b &amp;&amp; c &gt; &quot;d&quot; &#39;e&#39;");
	CHECK(base64("") == "");
	CHECK(base64("f") == "Zg==");
	CHECK(base64("fo") == "Zm8=");
	CHECK(base64("foo") == "Zm9v");
	CHECK(base64("foob") == "Zm9vYg==");
	CHECK(base64("fooba") == "Zm9vYmE=");
	CHECK(base64("foobar") == "Zm9vYmFy");
	CHECK(base64(std::string("\xff\x00", 2)) == "/wA=");
}

TEST_CASE("report: the heat map is white at z = 0, pale within the critical |z|, dark beyond, black for NaN") {
	double z_critical = 4.0;
	CHECK(z_colour(0.0f, z_critical) == z_colours::zero);
	CHECK(z_colour(4.0f, z_critical) == z_colours::noise_too_bright);
	CHECK(z_colour(-4.0f, z_critical) == z_colours::noise_too_dark);
	CHECK(z_colour(4.01f, z_critical) == z_colours::fail_too_bright);
	CHECK(z_colour(-INFINITY, z_critical) == z_colours::fail_too_dark);
	CHECK(z_colour(NAN, z_critical) == z_colours::not_a_number);
}

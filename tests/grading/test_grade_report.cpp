// The grade report's pieces (label report): what a task's status is, given the files ./lab report
// leaves (task_result.h), how the rubric scores them by test-case id and how it is rewritten by
// `rubric --update` of ./lab (rubric.h), the HTML helpers, and the heat map's colour scale.
#include "html.h"
#include "rubric.h"
#include "task_result.h"
#include "temp_dir.h"
#include "z_heat_map.h"

#include "lab_catch2.h"

#include <nlohmann/json.hpp>

#include <algorithm>
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
		std::string n = std::to_string(i++);
		cases += std::string(cases.empty() ? "" : ",") + R"({"id": "t1.case.)" + n + R"(", "name": "case )" + n +
		         R"(", "file": "tests/task1/x.cpp", "line": 3, "passed": )" + (p ? "true" : "false") +
		         R"(, "failures": [], "more_failures": 0, "attachments": []})";
	}
	for (int n = 0; n < (expected < 0 ? i : expected); n++) {
		names += std::string(names.empty() ? "" : ",") + R"({"id": "t1.case.)" + std::to_string(n) +
		         R"(", "name": "case )" + std::to_string(n) + R"("})";
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
	CHECK_THAT(some.why, contains_text("case 2"));
	std::string without_list = record(true, {true});
	std::string list = R"("expected_test_cases": [{"id": "t1.case.0", "name": "case 0"}], )";
	REQUIRE(without_list.find(list) != std::string::npos);
	without_list.erase(without_list.find(list), list.size());
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
	CHECK_THAT(crashed.why, contains_text("SIGSEGV"));
	CHECK(crashed.log_tail == "the grader's output\n");
	Task_Result timed_out = task1(timeout, "124", record(true, {false}, "SIGTERM - Termination request signal"));
	CHECK(timed_out.status == Status::crashed);
	CHECK_THAT(timed_out.why, contains_text("did not finish in time"));
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

namespace {

// One test case of a judge's record: its id, its title, whether it passed.
struct Recorded {
	std::string id, name;
	bool passed;
};

// Task 1's result from a record of a judge that ran all of `test_cases` to its summary.
Task_Result task1_ran(const Temp_Dir& dir, const std::vector<Recorded>& test_cases) {
	nlohmann::json listed = nlohmann::json::array(), results = nlohmann::json::array();
	for (const Recorded& c : test_cases) {
		listed.push_back({{"id", c.id}, {"name", c.name}});
		results.push_back({{"id", c.id}, {"name", c.name}, {"file", "tests/task1/x.cpp"}, {"line", 3},
		                   {"passed", c.passed}, {"failures", nlohmann::json::array()}, {"more_failures", 0},
		                   {"attachments", nlohmann::json::array()}});
	}
	nlohmann::json record{{"grader", "judge_task1"}, {"finished", true},       {"fatal_error", nullptr},
	                      {"running", nullptr},       {"expected_test_cases", listed}, {"test_cases", results}};
	bool all_passed = std::all_of(test_cases.begin(), test_cases.end(), [](const Recorded& c) { return c.passed; });
	return task1(dir, all_passed ? "0" : "1", record.dump());
}

// A rubric file of task 1 alone, worth 6 points.
std::string rubric_file(const Temp_Dir& dir, const std::string& test_cases) {
	std::ofstream(dir.file("rubric.json")) << R"({"tasks": [{"task": 1, "points": 6, "test_cases": [)" << test_cases
	                                       << "]}]}";
	return dir.file("rubric.json");
}

} // namespace

TEST_CASE("rubric: grades follow the test cases' ids: rewording a title, in a judge or in the rubric, changes no score") {
	Temp_Dir before_dir, after_dir;
	std::string test_cases = R"({"id": "t1.a.one", "title": "one", "weight": 2}, {"id": "t1.a.two", "title": "two"},)"
	                         R"( {"id": "t1.a.three", "title": "three", "weight": 0})";
	Rubric rubric = Rubric::read(rubric_file(before_dir, test_cases));
	Task_Score before = score(rubric, task1_ran(before_dir, {{"t1.a.one", "one", true},
	                                                           {"t1.a.two", "two", false},
	                                                           {"t1.a.three", "three", true}}));
	// The judge's three titles reworded, and the rubric's.
	std::string retitled = test_cases;
	for (std::string title : {"one", "two", "three"}) {
		std::string quoted = "\"" + title + "\"";
		retitled.replace(retitled.find(quoted), quoted.size(), "\"" + title + ", reworded in the rubric\"");
	}
	Rubric retitled_rubric = Rubric::read(rubric_file(after_dir, retitled));
	Task_Score after = score(retitled_rubric, task1_ran(after_dir, {{"t1.a.one", "the first, reworded", true},
	                                                                {"t1.a.two", "the second, reworded", false},
	                                                                {"t1.a.three", "the third, reworded", true}}));
	CHECK(before.score == Approx(4.0)); // 6 points * weight 2 / total weight 3; t1.a.two fails
	CHECK(before.max_score == Approx(6.0));
	CHECK(after.score == before.score);
	CHECK(after.max_score == before.max_score);
	REQUIRE(after.test_cases.size() == before.test_cases.size());
	for (size_t i = 0; i < before.test_cases.size(); i++) {
		CAPTURE(before.test_cases[i].id);
		CHECK(after.test_cases[i].id == before.test_cases[i].id);
		CHECK(after.test_cases[i].score == before.test_cases[i].score);
		CHECK(after.test_cases[i].max_score == before.test_cases[i].max_score);
		CHECK(after.test_cases[i].passed == before.test_cases[i].passed);
	}
	CHECK(after.test_cases[0].name == "the first, reworded"); // what students see is the judge's title
}

TEST_CASE("rubric: a judge's id the rubric lacks, a rubric id the judge lacks, or a test case without an id stops "
          "grading, naming the id") {
	Temp_Dir dir;
	Rubric rubric = Rubric::read(rubric_file(dir, R"({"id": "t1.a.one"}, {"id": "t1.a.two"})"));
	auto message_of = [&](const std::vector<Recorded>& test_cases) -> std::string {
		Temp_Dir records;
		try {
			score(rubric, task1_ran(records, test_cases));
		} catch (const Rubric_Error& problem) {
			return problem.what();
		}
		return "(no error)";
	};
	CHECK_NOTHROW(score(rubric, task1_ran(dir, {{"t1.a.one", "one", true}, {"t1.a.two", "two", true}})));
	std::string new_id = message_of({{"t1.a.one", "one", true}, {"t1.a.two", "two", true}, {"t1.a.new", "new", true}});
	CHECK_THAT(new_id, contains_text("t1.a.new") && contains_text("./lab rubric --update"));
	std::string gone_id = message_of({{"t1.a.one", "one", true}});
	CHECK_THAT(gone_id, contains_text("t1.a.two") && contains_text("./lab rubric --update"));
	std::string no_id = message_of({{"t1.a.one", "one", true}, {"t1.a.two", "two", true}, {"", "untagged", true}});
	CHECK_THAT(no_id, contains_text("\"untagged\" has no tag [id:ID]"));
}

TEST_CASE("rubric: a rubric that names test cases by title (from before the ids) is refused, with what to run") {
	Temp_Dir dir;
	std::string file = rubric_file(dir, R"({"name": "generate_ray: the centre of the film", "weight": 1})");
	CHECK_THROWS_WITH(Rubric::read(file), contains_text("no \"id\"") && contains_text("./lab rubric --update"));
}

TEST_CASE("rubric --update: ids kept with their fields, new ids at weight 1, gone ids dropped and listed, "
          "titles converted to ids") {
	Temp_Dir dir;
	std::string file = rubric_file(dir, R"({"id": "t1.a.kept", "title": "old title", "weight": 3, "visibility": "hidden"},)"
	                                    R"( {"name": "named by its title", "weight": 0, "penalty": 2},)"
	                                    R"( {"id": "t1.a.gone", "weight": 5})");
	Task_Result stubs;
	stubs.task = lab_tasks().at(0);
	stubs.expected = {{"t1.a.new", "a new test case"}, {"t1.a.kept", "new title"}, {"t1.a.titled", "named by its title"}};
	stubs.test_cases = {{"t1.a.new", "a new test case", "x.cpp:1", true, {}, 0, {}, {}}};
	Rubric_Update update = update_rubric(file, {stubs});

	nlohmann::json rubric = nlohmann::json::parse(update.text);
	const nlohmann::json& task = rubric["tasks"].at(0);
	CHECK(task["task"] == 1);
	CHECK(task["points"] == 6); // kept
	const nlohmann::json& cases = task["test_cases"];
	REQUIRE(cases.size() == 3); // in the judge's order
	CHECK(cases[0] == nlohmann::json{{"id", "t1.a.new"}, {"title", "a new test case"}, {"weight", 1}});
	CHECK(cases[1] == nlohmann::json{{"id", "t1.a.kept"}, {"title", "new title"}, {"weight", 3}, {"visibility", "hidden"}});
	CHECK(cases[2] == nlohmann::json{{"id", "t1.a.titled"}, {"title", "named by its title"}, {"weight", 0}, {"penalty", 2}});
	REQUIRE(update.changes.size() == 2);
	CHECK_THAT(update.changes[0], starts_with_text("added t1.a.new (task 1, weight 1)") &&
	                                  contains_text("the shipped stubs pass it"));
	CHECK_THAT(update.changes[1], starts_with_text("dropped t1.a.gone (task 1, weight 5)"));
	// What it writes, grading reads.
	std::ofstream(file) << update.text;
	CHECK(Rubric::read(file).tasks.at(1).test_cases.size() == 3);
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

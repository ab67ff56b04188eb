// The grade report's Catch2 listener (`./lab report`, grading/report/), in the judge (grading/judge/):
// only the judge writes the report's records. When LAB_REPORT_DIR is set, a grader writes
// <dir>/task<N>.json (report_record.h): per test case its id (its tag [id:ID], which the rubric
// grades by), its title, whether it passed and, for
// each failed check, where it is, what it checked and its messages (the INFO/CAPTURE text that
// tells the student what is wrong and where to look), and what checks attached (the images of a
// reference-image test). The file is rewritten after every test case, so a grader that crashes or
// is stopped leaves the test cases it finished and the one it was running.
//
// Linked into every grader as an object (tests/CMakeLists.txt): from a static library the linker
// would drop it, since nothing calls it.
#include "catch2_events.h"
#include "judge.h"
#include "report_record.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace {

using Json = nlohmann::ordered_json;

constexpr size_t MAX_FAILURES = 20; // recorded per test case; the others are only counted

// One failed check: where, what, and the messages that explain it.
Json failure_record(const catch2_seam::Failed_Check& check) {
	Json messages = Json::array();
	for (const catch2_seam::Message& message : check.messages) messages.push_back(message.text);
	return Json{{"kind", check.kind},           {"file", check.file},
	            {"line", check.line},           {"expression", check.expression},
	            {"expansion", check.expansion}, {"messages", messages}};
}

// The record of a test case: its id (its tag [id:ID], cmake/test_case_ids.cmake, or "" if it has
// none) and title.
Json test_case_record(const catch2_seam::Test_Case& test_case) {
	std::vector<std::string> ids = test_case.tagged("id:");
	return Json{{"id", ids.empty() ? "" : ids.front()}, {"name", test_case.name}};
}

class Report_Listener : public catch2_seam::Events {
public:
	// `all_test_cases`: every test case the judge has, whatever this run selected: a task passes only
	// when each ran.
	void run_starting(const std::string& program, const std::vector<catch2_seam::Test_Case>& all_test_cases) override {
		grader = program;
		for (const catch2_seam::Test_Case& test_case : all_test_cases) expected.push_back(test_case_record(test_case));
		write(false);
	}

	void test_case_starting(const catch2_seam::Test_Case& test_case) override {
		running = test_case_record(test_case);
		running.update(Json{{"file", test_case.file}, {"line", test_case.line}, {"passed", false},
		                    {"failures", Json::array()}, {"more_failures", 0}});
		report::take_attachments(); // none belong to this test case yet
		write(false);
	}

	void check_failed(const catch2_seam::Failed_Check& check) override {
		if (running.is_null()) return;
		// Catch2 reports a fatal signal (a crash, or the time limit's SIGTERM) as a failed check.
		if (check.kind == "crash") fatal_error = check.result_message;
		Json& failures = running["failures"];
		if (failures.size() < MAX_FAILURES) {
			failures.push_back(failure_record(check));
		} else {
			running["more_failures"] = running["more_failures"].get<size_t>() + 1;
		}
	}

	void test_case_ended(const catch2_seam::Test_Case&, catch2_seam::Counts checks) override {
		running["passed"] = checks.failed == 0;
		running["attachments"] = report::take_attachments();
		test_cases.push_back(std::exchange(running, Json()));
		write(false);
	}

	void run_ended(catch2_seam::Counts, catch2_seam::Counts) override {
		write(true);
	}

private:
	// Replaces the file whole (write, then rename), so a reader never sees half of it.
	void write(bool finished) const {
		if (!report::enabled()) return;
		Json record{{"grader", grader}, {"finished", finished}, {"fatal_error", fatal_error},
		            {"sandbox", judge::sandbox().notice()},
		            {"inputs", judge::inputs_are_secret() ? "drawn from the grading seed" : "the public test cases"},
		            {"expected_test_cases", expected}, {"running", running}, {"test_cases", test_cases}};
		std::string path = report::file(report::task_name() + ".json");
		std::filesystem::create_directories(report::directory());
		// Messages may quote any bytes a student's code produced: invalid UTF-8 is replaced, not thrown.
		std::ofstream(path + ".part") << record.dump(1, '\t', false, Json::error_handler_t::replace) << "\n";
		std::rename((path + ".part").c_str(), path.c_str());
	}

	std::string grader;
	Json running; // the test case in progress, null between test cases
	Json test_cases = Json::array();
	Json expected = Json::array(); // all the judge's test cases: {"id": ..., "name": ...}
	Json fatal_error; // the signal's name if the grader crashed, else null
};

} // namespace

LAB_CATCH2_LISTENER(Report_Listener)

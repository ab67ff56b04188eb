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
#include "judge.h"
#include "report_record.h"

#define CATCH_CONFIG_EXTERNAL_INTERFACES // the reporter and listener types
#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace {

using Json = nlohmann::ordered_json;

constexpr size_t MAX_FAILURES = 20; // recorded per test case; the others are only counted

std::string source_path(const char* file) {
	std::error_code error;
	std::filesystem::path relative = std::filesystem::proximate(file, error);
	return error ? std::string(file) : relative.string();
}

std::string result_kind(Catch::ResultWas::OfType type) {
	switch (type) {
	case Catch::ResultWas::ThrewException: return "unexpected exception";
	case Catch::ResultWas::DidntThrowException: return "expected an exception";
	case Catch::ResultWas::FatalErrorCondition: return "crash";
	case Catch::ResultWas::ExplicitFailure: return "failure";
	default: return "check";
	}
}

// A test case's id: ID of its tag [id:ID] (cmake/test_case_ids.cmake), or "" if it has none.
std::string test_case_id(const Catch::TestCaseInfo& info) {
	const std::string prefix = "id:";
	for (const std::string& tag : info.tags) {
		if (tag.rfind(prefix, 0) == 0) return tag.substr(prefix.size());
	}
	return "";
}

// One failed check: where, what, and the messages that explain it.
Json failure_record(const Catch::AssertionStats& stats) {
	const Catch::AssertionResult& result = stats.assertionResult;
	Json messages = Json::array();
	for (const Catch::MessageInfo& info : stats.infoMessages) messages.push_back(info.message);
	Catch::SourceLineInfo where = result.getSourceInfo();
	return Json{{"kind", result_kind(result.getResultType())},
	            {"file", source_path(where.file)},
	            {"line", where.line},
	            {"expression", result.hasExpression() ? result.getExpressionInMacro() : ""},
	            {"expansion", result.hasExpandedExpression() ? result.getExpandedExpression() : ""},
	            {"messages", messages}};
}

class Report_Listener : public Catch::TestEventListenerBase {
public:
	using TestEventListenerBase::TestEventListenerBase;

	void testRunStarting(const Catch::TestRunInfo& info) override {
		TestEventListenerBase::testRunStarting(info);
		grader = info.name;
		// Every test case the judge has, whatever this run selected: a task passes only when each ran.
		for (const Catch::TestCase& test_case : Catch::getAllTestCasesSorted(*m_config)) {
			expected.push_back(Json{{"id", test_case_id(test_case)}, {"name", test_case.name}});
		}
		write(false);
	}

	void testCaseStarting(const Catch::TestCaseInfo& info) override {
		TestEventListenerBase::testCaseStarting(info);
		running = Json{{"id", test_case_id(info)}, {"name", info.name}, {"file", source_path(info.lineInfo.file)},
		               {"line", info.lineInfo.line}, {"passed", false}, {"failures", Json::array()}, {"more_failures", 0}};
		report::take_attachments(); // none belong to this test case yet
		write(false);
	}

	bool assertionEnded(const Catch::AssertionStats& stats) override {
		if (stats.assertionResult.isOk() || running.is_null()) return false;
		// Catch2 reports a fatal signal (a crash, or the time limit's SIGTERM) as a failed assertion.
		if (stats.assertionResult.getResultType() == Catch::ResultWas::FatalErrorCondition) {
			fatal_error = stats.assertionResult.getMessage();
		}
		Json& failures = running["failures"];
		if (failures.size() < MAX_FAILURES) {
			failures.push_back(failure_record(stats));
		} else {
			running["more_failures"] = running["more_failures"].get<size_t>() + 1;
		}
		return false;
	}

	void testCaseEnded(const Catch::TestCaseStats& stats) override {
		TestEventListenerBase::testCaseEnded(stats);
		running["passed"] = stats.totals.assertions.failed == 0;
		running["attachments"] = report::take_attachments();
		test_cases.push_back(std::exchange(running, Json()));
		write(false);
	}

	void testRunEnded(const Catch::TestRunStats& stats) override {
		TestEventListenerBase::testRunEnded(stats);
		write(true);
	}

private:
	// Replaces the file whole (write, then rename), so a reader never sees half of it.
	void write(bool finished) const {
		if (!report::enabled()) return;
		Json record{{"grader", grader}, {"finished", finished}, {"fatal_error", fatal_error},
		            {"sandbox", judge::sandbox().notice()},
		            {"inputs", judge::secret_seed() ? "drawn from the grading seed" : "the public test cases"},
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

CATCH_REGISTER_LISTENER(Report_Listener)

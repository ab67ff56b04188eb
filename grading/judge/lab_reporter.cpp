// The judge's default reporter: each failed test case by its title, then what its failed checks
// say (at most SHOWN_CHECKS of them, a repeat only counted), in the test cases' own words and
// nothing else. Where a check is in tests/ and the C++ it
// evaluated (Catch2's "file:line: FAILED: CHECK( ok ) with expansion: false") would send a student
// reading the graders' code; instructors get them with LAB_GRADE_DETAILS=1 (or -r console), and the
// grade report keeps them folded away (report_listener.cpp). The run ends with Catch2's count line,
// "test cases: N | P passed | F failed", which ctest's stub checks read.
#include "lab_reporter.h"

#include "catch2_events.h"

#include <cstdlib>
#include <ostream>
#include <sstream>

const char* const LAB_REPORTER = "lab";

namespace {

using catch2_seam::Failed_Check;

constexpr size_t SHOWN_CHECKS = 5; // per test case; the others are counted
const std::string INDENT(6, ' ');

// `text` with every line indented.
void print_indented(std::ostream& out, const std::string& text) {
	std::istringstream lines(text);
	std::string line;
	while (std::getline(lines, line)) out << INDENT << line << "\n";
}

// What a failed check says: its messages, the variables it captured last. A crash of the judge is
// named as one; a check with no message at all (which a judge's checks should never be) shows what
// it evaluated.
std::vector<std::string> explanation(const Failed_Check& check) {
	std::vector<std::string> said, captured;
	for (const catch2_seam::Message& message : check.messages) {
		if (check.kind == "crash" && message.text == check.result_message) continue;
		(message.macro == "CAPTURE" ? captured : said).push_back(message.text);
	}
	if (check.kind == "crash") {
		said.insert(said.begin(), "The grader itself crashed (fatal error condition: " + check.result_message + ")");
	}
	if (said.empty()) {
		said.push_back(check.kind + " failed: " + check.expression +
		               (check.expansion.empty() ? "" : " with values " + check.expansion));
	}
	said.insert(said.end(), captured.begin(), captured.end());
	return said;
}

class Lab_Reporter : public catch2_seam::Events {
public:
	static constexpr const char* DESCRIPTION = "each failed test case with its checks' messages (the judge's "
	                                           "default; LAB_GRADE_DETAILS=1 adds where each check is)";

	explicit Lab_Reporter(std::ostream& out) : out(out), details(std::getenv("LAB_GRADE_DETAILS") != nullptr) {}

	void test_case_starting(const catch2_seam::Test_Case& test_case) override {
		name = test_case.name;
		shown = hidden = 0;
	}

	// A check that says what the one before it said (a loop's) is only counted.
	void check_failed(const Failed_Check& check) override {
		std::vector<std::string> said = explanation(check);
		if (shown == SHOWN_CHECKS || (shown > 0 && said == last_said)) {
			hidden++;
			return;
		}
		out << (shown == 0 ? "FAIL  " + name + "\n" : "\n");
		shown++;
		for (const std::string& text : said) print_indented(out, text);
		last_said = said;
		if (details) {
			print_indented(out, "(" + check.file + ":" + std::to_string(check.line) + ": " + check.expression +
			                        (check.expansion.empty() ? "" : " with expansion: " + check.expansion) + ")");
		}
		out.flush();
	}

	void test_case_ended(const catch2_seam::Test_Case&, catch2_seam::Counts) override {
		if (hidden > 0) out << INDENT << "(and " << hidden << " more failed checks in this test case)\n";
		if (shown > 0) out << "\n";
		out.flush();
	}

	// Catch2's own count line (with no "0 passed", as Catch2 writes it).
	void run_ended(catch2_seam::Counts test_cases, catch2_seam::Counts) override {
		out << "test cases: " << test_cases.passed + test_cases.failed;
		if (test_cases.passed > 0) out << " | " << test_cases.passed << " passed";
		if (test_cases.failed > 0) out << " | " << test_cases.failed << " failed";
		out << std::endl;
	}

private:
	std::ostream& out;
	bool details;
	std::string name; // of the running test case
	size_t shown = 0, hidden = 0; // its failed checks
	std::vector<std::string> last_said; // what its last shown check said
};

} // namespace

LAB_CATCH2_REPORTER("lab", Lab_Reporter)

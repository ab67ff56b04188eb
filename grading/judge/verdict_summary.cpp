// The order and the end of a judge's messages (judge.h): "fix NAME first" notes on test cases whose
// prerequisites failed, and the summary that ends the run, one line per failed test case (or the
// task's key figures when everything passed).
#include "catch2_events.h"
#include "judge.h"
#include "verdict_summary.h"

#include <iostream>
#include <set>
#include <vector>

namespace {

struct Failed_Test_Case {
	std::string name, first_message;
};

struct Summary_State {
	std::set<std::string> failed_functions; // NAME of [fn:NAME] tags of failed test cases
	std::vector<std::string> prerequisites_failed; // of the running test case
	std::vector<Failed_Test_Case> failed;
	std::vector<std::pair<std::string, std::string>> figures;
	size_t test_cases = 0;
	std::string first_message; // of the running test case's first failed check
};

Summary_State& summary() {
	static Summary_State s;
	return s;
}

std::string one_line(std::string text) {
	for (char& c : text) {
		if (c == '\n') c = ' ';
	}
	const size_t MAX = 110;
	return text.size() > MAX ? text.substr(0, MAX - 3) + "..." : text;
}

class Verdict_Order : public catch2_seam::Events {
public:
	void test_case_starting(const catch2_seam::Test_Case& test_case) override {
		Summary_State& s = summary();
		s.test_cases++;
		s.first_message.clear();
		s.prerequisites_failed.clear();
		for (const std::string& function : test_case.tagged("uses:")) {
			if (s.failed_functions.count(function)) s.prerequisites_failed.push_back(function);
		}
	}

	// Every section (the test case's own too) starts without messages: the note goes first.
	void section_starting() override {
		for (const std::string& function : summary().prerequisites_failed) {
			catch2_seam::push_note("Fix " + function + " first: its own test cases fail (above), and this test case "
			                       "uses it, so what follows may only be a consequence");
		}
	}

	void check_failed(const catch2_seam::Failed_Check& check) override {
		Summary_State& s = summary();
		if (!s.first_message.empty()) return;
		// The message that explains: the first that cites a handout section (§), else the first (never
		// the "fix first" note, never a CAPTURE of a variable).
		std::string first;
		for (const catch2_seam::Message& message : check.messages) {
			if (message.text.rfind("Fix ", 0) == 0 && !s.prerequisites_failed.empty()) continue;
			if (message.macro == "CAPTURE") continue;
			if (first.empty()) first = message.text;
			if (message.text.find("§") != std::string::npos) {
				s.first_message = message.text;
				break;
			}
		}
		if (s.first_message.empty()) s.first_message = first;
		if (s.first_message.empty()) s.first_message = check.result_message;
		if (s.first_message.empty()) s.first_message = check.expansion;
	}

	void test_case_ended(const catch2_seam::Test_Case& test_case, catch2_seam::Counts checks) override {
		Summary_State& s = summary();
		if (checks.failed == 0) return;
		for (const std::string& function : test_case.tagged("fn:")) s.failed_functions.insert(function);
		std::string prefix = s.prerequisites_failed.empty() ? "" : "(after " + s.prerequisites_failed.front() + ") ";
		s.failed.push_back({test_case.name, prefix + s.first_message});
	}
};

} // namespace

LAB_CATCH2_LISTENER(Verdict_Order)

namespace judge {

bool unit_tests_failed(const std::string& function) {
	return summary().failed_functions.count(function) > 0;
}

void key_figure(const std::string& what, const std::string& value) {
	summary().figures.emplace_back(what, value);
}

} // namespace judge

void print_verdict_summary(std::ostream& out) {
	const Summary_State& s = summary();
	if (s.test_cases == 0) return;
	if (s.failed.empty()) {
		out << "All " << s.test_cases << " test cases pass.\n";
		for (const auto& [what, value] : s.figures) out << "  " << what << ": " << value << "\n";
		return;
	}
	out << s.failed.size() << " of " << s.test_cases << " test cases fail:\n";
	for (const Failed_Test_Case& c : s.failed) out << "  x " << c.name << "\n      " << one_line(c.first_message) << "\n";
}

// The order and the end of a judge's messages (judge.h): "fix NAME first" notes on test cases whose
// prerequisites failed, and the summary that ends the run, one line per failed test case (or the
// task's key figures when everything passed).
#define CATCH_CONFIG_EXTERNAL_INTERFACES
#include <catch2/catch.hpp>

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

std::vector<std::string> tagged(const Catch::TestCaseInfo& info, const std::string& prefix) {
	std::vector<std::string> names;
	for (const std::string& tag : info.tags) {
		if (tag.rfind(prefix, 0) == 0) names.push_back(tag.substr(prefix.size()));
	}
	return names;
}

std::string one_line(std::string text) {
	for (char& c : text) {
		if (c == '\n') c = ' ';
	}
	const size_t MAX = 110;
	return text.size() > MAX ? text.substr(0, MAX - 3) + "..." : text;
}

class Verdict_Order : public Catch::TestEventListenerBase {
public:
	using TestEventListenerBase::TestEventListenerBase;

	void testCaseStarting(const Catch::TestCaseInfo& info) override {
		TestEventListenerBase::testCaseStarting(info);
		Summary_State& s = summary();
		s.test_cases++;
		s.first_message.clear();
		s.prerequisites_failed.clear();
		for (const std::string& function : tagged(info, "uses:")) {
			if (s.failed_functions.count(function)) s.prerequisites_failed.push_back(function);
		}
	}

	// Every section (the test case's own too) starts without messages: the note goes first.
	void sectionStarting(const Catch::SectionInfo& info) override {
		TestEventListenerBase::sectionStarting(info);
		for (const std::string& function : summary().prerequisites_failed) {
			Catch::MessageInfo note("INFO", info.lineInfo, Catch::ResultWas::Info);
			note.message = "Fix " + function + " first: its own test cases fail (above), and this test case uses it, "
			               "so what follows may only be a consequence";
			Catch::getResultCapture().pushScopedMessage(note);
		}
	}

	bool assertionEnded(const Catch::AssertionStats& stats) override {
		Summary_State& s = summary();
		if (stats.assertionResult.isOk() || !s.first_message.empty()) return false;
		// The message that explains: the first that cites a handout section (§), else the first (never
		// the "fix first" note, never a CAPTURE of a variable).
		std::string first;
		for (const Catch::MessageInfo& info : stats.infoMessages) {
			if (info.message.rfind("Fix ", 0) == 0 && !s.prerequisites_failed.empty()) continue;
			if (info.macroName == "CAPTURE") continue;
			if (first.empty()) first = info.message;
			if (info.message.find("§") != std::string::npos) {
				s.first_message = info.message;
				break;
			}
		}
		if (s.first_message.empty()) s.first_message = first;
		if (s.first_message.empty()) s.first_message = stats.assertionResult.getMessage();
		if (s.first_message.empty()) s.first_message = stats.assertionResult.getExpandedExpression();
		return false;
	}

	void testCaseEnded(const Catch::TestCaseStats& stats) override {
		TestEventListenerBase::testCaseEnded(stats);
		Summary_State& s = summary();
		if (stats.totals.assertions.failed == 0) return;
		for (const std::string& function : tagged(stats.testInfo, "fn:")) s.failed_functions.insert(function);
		std::string prefix = s.prerequisites_failed.empty() ? "" : "(after " + s.prerequisites_failed.front() + ") ";
		s.failed.push_back({stats.testInfo.name, prefix + s.first_message});
	}
};

} // namespace

CATCH_REGISTER_LISTENER(Verdict_Order)

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

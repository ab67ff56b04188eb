#include "rubric.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <set>

namespace {

const std::set<std::string> VISIBILITIES{"visible", "after_published", "after_due_date", "hidden"};

// What a failed test case tells the student: its failed checks' messages, once each.
std::string output_of(const Test_Case& c) {
	std::string text;
	for (const Failure& failure : c.failures) {
		std::string messages;
		for (const std::string& m : failure.messages) messages += m + "\n";
		if (messages.empty()) messages = failure.expansion + "\n";
		if (text.find(messages) == std::string::npos) text += messages;
	}
	if (c.more_failures > 0) text += "... and " + std::to_string(c.more_failures) + " more failed checks\n";
	return text;
}

} // namespace

double Rubric::Task::total_weight() const {
	double total = 0.0;
	for (const Test_Case& c : test_cases) total += c.weight;
	return total;
}

double Rubric::Task::penalty(const Test_Case& c) const {
	if (c.weight > 0.0) return 0.0;
	if (c.penalty >= 0.0) return c.penalty;
	size_t weighted = 0;
	for (const Test_Case& other : test_cases) weighted += other.weight > 0.0;
	return weighted == 0 ? 0.0 : points / double(weighted);
}

Rubric Rubric::read(const std::filesystem::path& file) {
	std::ifstream in(file);
	if (!in) throw Rubric_Error(file.string() + ": cannot be read");
	nlohmann::json json = nlohmann::json::parse(in, nullptr, false);
	if (json.is_discarded() || !json.contains("tasks") || !json["tasks"].is_array()) {
		throw Rubric_Error(file.string() + ": expected a JSON object with an array \"tasks\"");
	}
	Rubric rubric;
	for (const auto& task : json["tasks"]) {
		std::string where = file.string() + ": tasks[" + std::to_string(rubric.tasks.size()) + "]";
		if (!task.contains("task") || !task["task"].is_number_integer() || !task.contains("points") ||
		    !task["points"].is_number() || !task.contains("test_cases") || !task["test_cases"].is_array()) {
			throw Rubric_Error(where + ": expected \"task\" (1-7), \"points\" and \"test_cases\"");
		}
		int number = task["task"];
		if (number < 1 || number > 7 || rubric.tasks.count(number)) {
			throw Rubric_Error(where + ": task " + std::to_string(number) + " is not 1-7 or appears twice");
		}
		Task t;
		t.points = task["points"];
		if (!(t.points >= 0.0)) throw Rubric_Error(where + ": points must not be negative");
		for (const auto& c : task["test_cases"]) {
			Test_Case test_case;
			test_case.name = c.value("name", "");
			test_case.weight = c.value("weight", 1.0);
			test_case.penalty = c.value("penalty", -1.0);
			test_case.visibility = c.value("visibility", "visible");
			if (test_case.name.empty() || !(test_case.weight >= 0.0) || !VISIBILITIES.count(test_case.visibility)) {
				throw Rubric_Error(where + ": a test case needs a \"name\", a weight >= 0 and a visibility of "
				                           "visible, after_published, after_due_date or hidden");
			}
			t.test_cases.push_back(test_case);
		}
		if (t.points > 0.0 && !(t.total_weight() > 0.0)) throw Rubric_Error(where + ": points but no weight");
		rubric.tasks[number] = t;
	}
	return rubric;
}

Task_Score score(const Rubric& rubric, const Task_Result& result) {
	int number = result.task.number;
	auto found = rubric.tasks.find(number);
	if (found == rubric.tasks.end()) throw Rubric_Error("the rubric has no task " + std::to_string(number));
	const Rubric::Task& task = found->second;
	Task_Score score;
	score.task = number;
	score.max_score = task.points;
	// Every test case the judge has must be in the rubric (a task that did not run has none).
	std::vector<std::string> judged = result.expected;
	for (const std::string& name : judged) {
		bool known = std::any_of(task.test_cases.begin(), task.test_cases.end(),
		                         [&](const Rubric::Test_Case& c) { return c.name == name; });
		if (!known) throw Rubric_Error("task " + std::to_string(number) + ": the rubric has no test case \"" + name + "\"");
	}
	for (const Rubric::Test_Case& entry : task.test_cases) {
		if (!judged.empty() && std::find(judged.begin(), judged.end(), entry.name) == judged.end()) {
			throw Rubric_Error("task " + std::to_string(number) + ": the rubric's test case \"" + entry.name +
			                   "\" is not one of the judge's");
		}
		Scored_Test_Case scored;
		scored.name = entry.name;
		scored.visibility = entry.visibility;
		scored.max_score = task.total_weight() > 0.0 ? task.points * entry.weight / task.total_weight() : 0.0;
		auto ran = std::find_if(result.test_cases.begin(), result.test_cases.end(),
		                        [&](const Test_Case& c) { return c.name == entry.name; });
		if (result.status == Status::not_run) {
			scored.output = result.why;
		} else if (ran == result.test_cases.end()) {
			scored.output = "This test case did not run. " + result.why;
		} else {
			scored.passed = ran->passed;
			scored.output = ran->passed ? "" : output_of(*ran);
		}
		scored.score = scored.passed ? scored.max_score : -task.penalty(entry);
		score.score += scored.score;
		score.test_cases.push_back(scored);
	}
	score.score = std::max(0.0, score.score);
	return score;
}

void write_default_rubric(std::ostream& out, const std::vector<Task_Result>& stubs) {
	const std::map<int, double> POINTS{{1, 5}, {2, 15}, {3, 18}, {4, 15}, {5, 15}, {6, 8}, {7, 14}};
	nlohmann::ordered_json tasks = nlohmann::ordered_json::array();
	for (const Task_Result& result : stubs) {
		if (result.expected.empty()) throw Rubric_Error("task " + std::to_string(result.task.number) + " has no test cases: " + result.why);
		nlohmann::ordered_json cases = nlohmann::ordered_json::array();
		for (const std::string& name : result.expected) {
			auto ran = std::find_if(result.test_cases.begin(), result.test_cases.end(),
			                        [&](const Test_Case& c) { return c.name == name; });
			bool stub_passes = ran != result.test_cases.end() && ran->passed;
			cases.push_back({{"name", name}, {"weight", stub_passes ? 0 : 1}});
		}
		tasks.push_back({{"task", result.task.number}, {"points", POINTS.at(result.task.number)}, {"test_cases", cases}});
	}
	nlohmann::ordered_json rubric{{"about", "Points per task and their split over its test cases (tests/report/rubric.h). "
	                                        "Weight 0: a requirement the shipped stubs pass, which earns nothing by itself "
	                                        "and costs a test case's average points when it fails."},
	                              {"tasks", tasks}};
	out << rubric.dump(1, '\t') << "\n";
}

#include "rubric.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <set>

namespace {

using Json = nlohmann::ordered_json;

const std::set<std::string> VISIBILITIES{"visible", "after_published", "after_due_date", "hidden"};
const std::map<int, double> DEFAULT_POINTS{{1, 5}, {2, 15}, {3, 18}, {4, 15}, {5, 15}, {6, 8}, {7, 14}, {8, 0}};
const char* const ABOUT = "Points per task and their split over its test cases (grading/report/rubric.h), each named by "
                          "the id of its judge's TEST_CASE (its tag [id:ID]; the title is a reminder, grading ignores "
                          "it). Weight 0: a requirement the shipped stubs pass, which earns nothing by itself and "
                          "costs a test case's average points when it fails. Task 8 (adaptive sampling) is an optional "
                          "extension, worth 0 points unless the course gives it some.";

// Every test case of a judge that ran has an id (the configuration checks it: cmake/test_case_ids.cmake).
void check_ids(const Task_Result& result) {
	for (const Listed_Test_Case& listed : result.expected) {
		if (listed.id.empty()) {
			throw Rubric_Error("task " + std::to_string(result.task.number) + ": the judge's test case \"" + listed.name +
			                   "\" has no tag [id:ID] (cmake/test_case_ids.cmake)");
		}
	}
}

// A judge's list of test cases, to write a rubric from: there is one, and each has an id.
void check_listed(const Task_Result& result) {
	if (result.expected.empty()) {
		throw Rubric_Error("task " + std::to_string(result.task.number) + " has no test cases: " + result.why);
	}
	check_ids(result);
}

bool stubs_pass(const Task_Result& stubs, const std::string& id) {
	return std::any_of(stubs.test_cases.begin(), stubs.test_cases.end(),
	                   [&](const Test_Case& c) { return c.id == id && c.passed; });
}

// The index in a rubric's test cases of the entry of a judge's test case: the entry of its id, or in a
// rubric from before the ids the entry named by its title; test_cases.size() if there is none.
size_t find_entry(const Json& test_cases, const Listed_Test_Case& listed) {
	for (size_t i = 0; i < test_cases.size(); i++) {
		if (test_cases[i].is_object() && test_cases[i].value("id", "") == listed.id) return i;
	}
	for (size_t i = 0; i < test_cases.size(); i++) {
		const Json& entry = test_cases[i];
		if (entry.is_object() && !entry.contains("id") && entry.value("name", "") == listed.name) return i;
	}
	return test_cases.size();
}

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
	std::set<std::string> ids;
	for (const auto& task : json["tasks"]) {
		std::string where = file.string() + ": tasks[" + std::to_string(rubric.tasks.size()) + "]";
		if (!task.contains("task") || !task["task"].is_number_integer() || !task.contains("points") ||
		    !task["points"].is_number() || !task.contains("test_cases") || !task["test_cases"].is_array()) {
			throw Rubric_Error(where + ": expected \"task\" (1-8), \"points\" and \"test_cases\"");
		}
		int number = task["task"];
		if (number < 1 || number > 8 || rubric.tasks.count(number)) {
			throw Rubric_Error(where + ": task " + std::to_string(number) + " is not 1-8 or appears twice");
		}
		Task t;
		t.points = task["points"];
		if (!(t.points >= 0.0)) throw Rubric_Error(where + ": points must not be negative");
		for (const auto& c : task["test_cases"]) {
			if (c.is_object() && !c.contains("id") && c.contains("name")) {
				throw Rubric_Error(where + ": the test case \"" + c.value("name", "") + "\" has a \"name\" but no \"id\": "
				                   "the rubric names test cases by id now; `./lab rubric --update` converts it");
			}
			if (!c.is_object() || !c.contains("id") || !c["id"].is_string()) {
				throw Rubric_Error(where + ": a test case needs an \"id\", its judge's tag [id:ID]");
			}
			Test_Case test_case;
			test_case.id = c["id"];
			test_case.title = c.value("title", "");
			test_case.weight = c.value("weight", 1.0);
			test_case.penalty = c.value("penalty", -1.0);
			test_case.visibility = c.value("visibility", "visible");
			if (test_case.id.empty() || !(test_case.weight >= 0.0) || !VISIBILITIES.count(test_case.visibility)) {
				throw Rubric_Error(where + ": a test case needs an \"id\", a weight >= 0 and a visibility of "
				                           "visible, after_published, after_due_date or hidden");
			}
			if (!ids.insert(test_case.id).second) throw Rubric_Error(where + ": the id " + test_case.id + " appears twice");
			t.test_cases.push_back(test_case);
		}
		if (t.points > 0.0 && !(t.total_weight() > 0.0)) throw Rubric_Error(where + ": points but no weight");
		rubric.tasks[number] = t;
	}
	return rubric;
}

Task_Score score(const Rubric& rubric, const Task_Result& result) {
	int number = result.task.number;
	std::string task_name = "task " + std::to_string(number);
	auto found = rubric.tasks.find(number);
	if (found == rubric.tasks.end()) throw Rubric_Error("the rubric has no " + task_name);
	const Rubric::Task& task = found->second;
	Task_Score score;
	score.task = number;
	score.max_score = task.points;
	// Every test case the judge has must be in the rubric (a task that did not run has none).
	check_ids(result);
	for (const Listed_Test_Case& listed : result.expected) {
		bool known = std::any_of(task.test_cases.begin(), task.test_cases.end(),
		                         [&](const Rubric::Test_Case& c) { return c.id == listed.id; });
		if (!known) {
			throw Rubric_Error(task_name + ": the rubric has no test case " + listed.id + " (\"" + listed.name +
			                   "\"): run `./lab rubric --update`");
		}
	}
	for (const Rubric::Test_Case& entry : task.test_cases) {
		auto listed = std::find_if(result.expected.begin(), result.expected.end(),
		                           [&](const Listed_Test_Case& c) { return c.id == entry.id; });
		if (!result.expected.empty() && listed == result.expected.end()) {
			throw Rubric_Error(task_name + ": the rubric's test case " + entry.id +
			                   " is not one of the judge's: run `./lab rubric --update`");
		}
		Scored_Test_Case scored;
		scored.id = entry.id;
		scored.name = listed != result.expected.end() ? listed->name : entry.title.empty() ? entry.id : entry.title;
		scored.visibility = entry.visibility;
		scored.max_score = task.total_weight() > 0.0 ? task.points * entry.weight / task.total_weight() : 0.0;
		auto ran = std::find_if(result.test_cases.begin(), result.test_cases.end(),
		                        [&](const Test_Case& c) { return c.id == entry.id; });
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
	Json tasks = Json::array();
	for (const Task_Result& result : stubs) {
		check_listed(result);
		Json cases = Json::array();
		for (const Listed_Test_Case& listed : result.expected) {
			cases.push_back({{"id", listed.id}, {"title", listed.name}, {"weight", stubs_pass(result, listed.id) ? 0 : 1}});
		}
		tasks.push_back({{"task", result.task.number}, {"points", DEFAULT_POINTS.at(result.task.number)}, {"test_cases", cases}});
	}
	out << Json{{"about", ABOUT}, {"tasks", tasks}}.dump(1, '\t') << "\n";
}

Rubric_Update update_rubric(const std::filesystem::path& file, const std::vector<Task_Result>& stubs) {
	std::ifstream in(file);
	if (!in) throw Rubric_Error(file.string() + ": cannot be read");
	Json old = Json::parse(in, nullptr, false);
	if (old.is_discarded() || !old.contains("tasks") || !old["tasks"].is_array()) {
		throw Rubric_Error(file.string() + ": expected a JSON object with an array \"tasks\"");
	}
	Rubric_Update update;
	Json tasks = Json::array();
	for (const Task_Result& result : stubs) {
		check_listed(result);
		int number = result.task.number;
		std::string task_name = "task " + std::to_string(number);
		auto old_task = std::find_if(old["tasks"].begin(), old["tasks"].end(), [&](const Json& t) {
			return t.is_object() && t.value("task", Json()) == number;
		});
		Json task = old_task != old["tasks"].end() ? *old_task : Json{{"points", DEFAULT_POINTS.at(number)}};
		if (old_task == old["tasks"].end()) {
			update.changes.push_back("added " + task_name + " at " + task["points"].dump() + " points");
		}
		Json old_cases = task.value("test_cases", Json::array());
		std::vector<bool> kept(old_cases.size(), false);
		Json cases = Json::array();
		for (const Listed_Test_Case& listed : result.expected) {
			size_t i = find_entry(old_cases, listed);
			if (i == old_cases.size()) {
				cases.push_back({{"id", listed.id}, {"title", listed.name}, {"weight", 1}});
				update.changes.push_back("added " + listed.id + " (" + task_name + ", weight 1): \"" + listed.name + "\"" +
				                         (stubs_pass(result, listed.id) ? "; the shipped stubs pass it: weight 0 would "
				                                                          "make it a requirement"
				                                                        : ""));
				continue;
			}
			kept[i] = true;
			Json entry{{"id", listed.id}, {"title", listed.name}};
			for (const auto& field : old_cases[i].items()) {
				if (field.key() != "id" && field.key() != "title" && field.key() != "name") entry[field.key()] = field.value();
			}
			cases.push_back(entry);
		}
		for (size_t i = 0; i < old_cases.size(); i++) {
			if (kept[i]) continue;
			const Json& entry = old_cases[i];
			std::string name = entry.is_object() ? entry.value("id", entry.value("name", entry.dump())) : entry.dump();
			std::string weight = entry.is_object() && entry.contains("weight") ? entry["weight"].dump() : "1";
			update.changes.push_back("dropped " + name + " (" + task_name + ", weight " + weight +
			                         "): the judge has no such test case");
		}
		Json updated{{"task", number}};
		for (const auto& field : task.items()) {
			if (field.key() != "task" && field.key() != "test_cases") updated[field.key()] = field.value();
		}
		updated["test_cases"] = cases;
		tasks.push_back(updated);
	}
	Json rubric{{"about", ABOUT}};
	for (const auto& field : old.items()) {
		if (field.key() != "about" && field.key() != "tasks") rubric[field.key()] = field.value();
	}
	rubric["tasks"] = tasks;
	update.text = rubric.dump(1, '\t') + "\n";
	return update;
}

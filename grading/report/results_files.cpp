#include "results_files.h"

#include "html.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace {

// Text for XML: escaped, and without the control characters XML 1.0 forbids (a student's code may
// print any bytes).
std::string xml_text(const std::string& text) {
	std::string clean = text;
	for (char& c : clean) {
		if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t' && c != '\r') c = '?';
	}
	return escape(clean);
}

// Points as Gradescope shows them: rounded to a hundredth, so reruns print the same numbers.
double rounded(double points) {
	return std::round(points * 100.0) / 100.0;
}

} // namespace

void write_gradescope_results(std::ostream& out, const std::vector<Task_Score>& scores,
                              const std::vector<Task_Result>& results, double execution_time,
                              const std::string& output) {
	nlohmann::ordered_json tests = nlohmann::ordered_json::array();
	double total = 0.0;
	for (size_t i = 0; i < scores.size(); i++) {
		const Task_Score& task = scores[i];
		total += task.score;
		for (const Scored_Test_Case& c : task.test_cases) {
			std::string why = results[i].sandbox.empty() ? "" : "\n(" + results[i].sandbox + "; inputs: " + results[i].inputs + ")";
			tests.push_back({{"name", "Task " + std::to_string(task.task) + ": " + c.name},
			                 {"score", rounded(c.score)},
			                 {"max_score", rounded(c.max_score)},
			                 {"output", c.passed ? "passed" : c.output + why},
			                 {"visibility", c.visibility}});
		}
	}
	nlohmann::ordered_json results_json{{"score", rounded(total)},
	                                    {"execution_time", std::lround(execution_time)},
	                                    {"output", output},
	                                    {"tests", tests}};
	out << results_json.dump(1, '\t', false, nlohmann::ordered_json::error_handler_t::replace) << "\n";
}

void write_junit(std::ostream& out, const std::vector<Task_Score>& scores) {
	out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites>\n";
	for (const Task_Score& task : scores) {
		size_t failures = 0;
		for (const Scored_Test_Case& c : task.test_cases) failures += !c.passed;
		out << "<testsuite name=\"task" << task.task << "\" tests=\"" << task.test_cases.size() << "\" failures=\""
		    << failures << "\">\n";
		for (const Scored_Test_Case& c : task.test_cases) {
			out << "<testcase classname=\"task" << task.task << "\" name=\"" << xml_text(c.name) << "\"";
			if (c.passed) {
				out << "/>\n";
			} else {
				std::string first_line = c.output.substr(0, c.output.find('\n'));
				out << ">\n<failure message=\"" << xml_text(first_line) << "\">" << xml_text(c.output)
			    << "</failure>\n</testcase>\n";
			}
		}
		out << "</testsuite>\n";
	}
	out << "</testsuites>\n";
}

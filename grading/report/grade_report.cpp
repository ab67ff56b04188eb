// grade_report DIR [--rubric FILE [--execution-time SECONDS]]: reads what `./lab report` or
// grade-submission left in DIR (task_result.h) and writes DIR/index.html, the grade report
// (report_page.h); prints each task's status, then the page's path. With a rubric (rubric.h) it also
// scores each task and writes DIR/results.json (Gradescope's format), DIR/junit.xml
// (results_files.h) and DIR/points.csv (each task's points and the total, for a gradebook), and
// prints the points.
//
// grade_report STUB_RESULTS --write-default-rubric FILE (the instructors' `rubric` in ./lab) writes the
// default rubric for the judges' test cases as the stubs' results list them; --update-rubric FILE
// (`rubric --update`) brings FILE up to date with them and prints what it added and dropped.
#include "report_page.h"
#include "results_files.h"
#include "rubric.h"
#include "task_result.h"

#include <cstdio>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <iostream>

namespace {
std::string now() {
	std::time_t t = std::time(nullptr);
	char text[64];
	std::strftime(text, sizeof text, "%Y-%m-%d %H:%M", std::localtime(&t));
	return text;
}
} // namespace

int main(int argc, char** argv) {
	std::vector<std::string> args(argv + 1, argv + argc);
	std::string rubric_file, default_rubric_file, rubric_to_update;
	double execution_time = 0.0;
	for (size_t i = 1; i + 1 < args.size(); i += 2) {
		if (args[i] == "--rubric") rubric_file = args[i + 1];
		else if (args[i] == "--execution-time") execution_time = std::stod(args[i + 1]);
		else if (args[i] == "--write-default-rubric") default_rubric_file = args[i + 1];
		else if (args[i] == "--update-rubric") rubric_to_update = args[i + 1];
		else args.clear();
	}
	if (args.empty() || args.size() % 2 == 0) {
		std::cerr << "usage: grade_report DIR [--rubric FILE [--execution-time SECONDS]]\n"
		             "       grade_report STUB_RESULTS --write-default-rubric FILE   (./lab rubric)\n"
		             "       grade_report STUB_RESULTS --update-rubric FILE          (./lab rubric --update)\n";
		return 2;
	}
	std::filesystem::path dir = args[0];
	std::vector<Task_Result> tasks;
	for (const Task_Info& task : lab_tasks()) tasks.push_back(read_task_result(dir, task));
	if (!default_rubric_file.empty()) {
		try {
			std::ofstream out(default_rubric_file);
			write_default_rubric(out, tasks);
			if (!out) throw Rubric_Error("cannot write " + default_rubric_file);
		} catch (const Rubric_Error& problem) {
			std::cerr << "grade_report: " << problem.what() << "\n";
			return 1;
		}
		std::cout << default_rubric_file << "\n";
		return 0;
	}
	if (!rubric_to_update.empty()) {
		try {
			Rubric_Update update = update_rubric(rubric_to_update, tasks);
			std::ofstream out(rubric_to_update);
			out << update.text;
			if (!out.flush()) throw Rubric_Error("cannot write " + rubric_to_update);
			for (const std::string& change : update.changes) std::cerr << "rubric: " << change << "\n";
			if (update.changes.empty()) std::cerr << "rubric: no test case added or dropped\n";
			Rubric::read(rubric_to_update); // still one that grading accepts (e.g. a task's points with no weight)
		} catch (const Rubric_Error& problem) {
			std::cerr << "grade_report: " << problem.what() << "\n";
			return 1;
		}
		std::cout << rubric_to_update << "\n";
		return 0;
	}
	std::vector<Task_Score> scores;
	if (!rubric_file.empty()) {
		try {
			Rubric rubric = Rubric::read(rubric_file);
			for (const Task_Result& t : tasks) scores.push_back(score(rubric, t));
		} catch (const Rubric_Error& problem) {
			std::cerr << "grade_report: " << problem.what() << "\n";
			return 1;
		}
	}
	std::filesystem::path page = dir / "index.html";
	std::ofstream out(page);
	write_report_page(out, tasks, now());
	if (!out) {
		std::cerr << "grade_report: cannot write " << page.string() << "\n";
		return 1;
	}
	for (const Task_Result& t : tasks) {
		std::cerr << "task " << t.task.number << " (" << t.task.title << "): " << status_name(t.status) << ". " << t.why
		          << "\n";
	}
	if (!scores.empty()) {
		std::ofstream results(dir / "results.json"), junit(dir / "junit.xml");
		std::string summary;
		double total = 0.0, most = 0.0;
		for (size_t i = 0; i < scores.size(); i++) {
			char line[160];
			std::snprintf(line, sizeof line, "task %d: %.2f of %.2f points (%s)\n", scores[i].task, scores[i].score,
			              scores[i].max_score, status_name(tasks[i].status).c_str());
			summary += line;
			total += scores[i].score;
			most += scores[i].max_score;
		}
		char line[80];
		std::snprintf(line, sizeof line, "total: %.2f of %.2f points\n", total, most);
		summary += line;
		for (const Task_Result& t : tasks) {
			if (t.sandbox.empty()) continue;
			summary += "How the code ran: " + t.sandbox + "; inputs: " + t.inputs + "\n";
			break;
		}
		write_gradescope_results(results, scores, tasks, execution_time, summary);
		write_junit(junit, scores);
		// One line for a gradebook (grade-class): the points of each task, then the total.
		std::ofstream points(dir / "points.csv");
		for (const Task_Score& s : scores) points << std::fixed << std::setprecision(2) << s.score << ",";
		points << std::fixed << std::setprecision(2) << total << "\n";
		if (!results || !junit || !points) {
			std::cerr << "grade_report: cannot write results.json, junit.xml or points.csv in " << dir.string() << "\n";
			return 1;
		}
		std::cerr << summary;
	}
	std::cout << page.string() << "\n";
	return 0;
}

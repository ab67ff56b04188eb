// grade_report DIR: reads what `./lab report` left in DIR (task_result.h) and writes DIR/index.html,
// the student's grade report (report_page.h); prints each task's status, then the page's path.
#include "report_page.h"
#include "task_result.h"

#include <ctime>
#include <fstream>
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
	if (argc != 2) {
		std::cerr << "usage: grade_report DIR   (./lab report runs it)\n";
		return 2;
	}
	std::filesystem::path dir = argv[1];
	std::vector<Task_Result> tasks;
	for (const Task_Info& task : lab_tasks()) tasks.push_back(read_task_result(dir, task));
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
	std::cout << page.string() << "\n";
	return 0;
}

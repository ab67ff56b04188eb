#pragma once
// What a grader records for the grade report (`./lab report`, grading/report/). Nothing is recorded
// unless the environment variable LAB_REPORT_DIR names a directory: then the Catch2 listener
// (report_listener.cpp) writes <dir>/task<N>.json, and checks may attach items (e.g. the images of
// a reference-image test) to the test case that is running.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace report {

bool enabled();          // LAB_REPORT_DIR is set and not empty
std::string directory(); // LAB_REPORT_DIR
// "task<N>": N from LAB_REPORT_TASK, else from the executable's name (grader_task<N>_student);
// the executable's name if it names no task. Names the grader's files in directory().
std::string task_name();
std::string file(const std::string& name); // directory()/name

// Attaches an item to the running test case; the listener takes them when the test case ends.
void attach(nlohmann::ordered_json item);
std::vector<nlohmann::ordered_json> take_attachments();

} // namespace report

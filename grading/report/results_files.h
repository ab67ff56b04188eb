#pragma once
// What a course platform reads of a graded submission, from the judges' results scored by the
// rubric (rubric.h):
// - results.json in Gradescope's autograder format: top-level score, execution_time, output, and
//   tests[] with name, score, max_score, output and visibility;
// - junit.xml: one <testsuite> per task, one <testcase> per test case, a <failure> for each failed one.
#include "rubric.h"

#include <ostream>
#include <string>
#include <vector>

void write_gradescope_results(std::ostream& out, const std::vector<Task_Score>& scores,
                              const std::vector<Task_Result>& results, double execution_time,
                              const std::string& output);
void write_junit(std::ostream& out, const std::vector<Task_Score>& scores);

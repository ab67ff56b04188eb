#pragma once
// The lines that end a judge's output (verdict_summary.cpp): one per failed test case with its first
// message, or the task's key figures when every test case passed.
#include <ostream>

void print_verdict_summary(std::ostream& out);

#pragma once
// The grade report as one self-contained HTML page: a summary table, then per task its status,
// the failed checks with their messages, and for each reference-image test the render, the
// reference and the heat map of z-scores side by side. No script, no external file: images are
// embedded as data: URIs, so the page reads the same from any folder, without a server.
#include "task_result.h"

#include <ostream>
#include <string>
#include <vector>

void write_report_page(std::ostream& out, const std::vector<Task_Result>& tasks, const std::string& made_at);

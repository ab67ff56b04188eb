#pragma once
// lab_viewer's command line (./lab view builds it): parsing with one clear error per mistake.
#include "viewer_session.h"

#include <string>
#include <vector>

struct Viewer_Options {
	Viewer_Config session;
	int port = 8024;
};

// args as in argv. Throws Input_Error naming the bad option or value.
Viewer_Options parse_viewer_options(const std::vector<std::string>& args);
std::string viewer_usage();

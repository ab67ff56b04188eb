// The judge's runner (grading/judge/judge.cpp), the same with Catch2 2 and 3 (lab_catch2.h): its
// command-line parser, its default reporter, and whether a run only lists. Catch2 2 compiles its
// runner where this is included (one file of a program); Catch2 3 links it from its library.
#pragma once

#if LAB_CATCH2_MAJOR == 2
#define CATCH_CONFIG_RUNNER
#include "catch2_events.h"
#else
#include "catch2_events.h"
#include <catch2/catch_session.hpp>
#include <catch2/internal/catch_reporter_spec_parser.hpp>
#endif

#include <string>

namespace catch2_seam {

// Catch2's command-line parser (Catch2 2: clara, 3: Clara), for a main's own options.
#if LAB_CATCH2_MAJOR == 2
namespace cli = Catch::clara;
#else
namespace cli = Catch::Clara;
#endif

// Parses the command line into `session`, running the reporter `reporter` unless the command line
// names one (-r). Accepts Catch2 2's --list-test-names-only with Catch2 3 too (its --list-tests
// --verbosity quiet). Returns Catch2's status: non-zero for a bad command line.
inline int apply_command_line(Catch::Session& session, int argc, char** argv, const std::string& reporter) {
#if LAB_CATCH2_MAJOR == 2
	session.configData().reporterName = reporter;
	return session.applyCommandLine(argc, argv);
#else
	bool names_only = false;
	session.cli(session.cli() | cli::Opt(names_only)["--list-test-names-only"]("list the test cases' names only"));
	if (int status = session.applyCommandLine(argc, argv)) return status;
	Catch::ConfigData& data = session.configData();
	if (names_only) data.listTests = true, data.verbosity = Catch::Verbosity::Quiet;
	if (data.reporterSpecifications.empty()) data.reporterSpecifications.push_back(*Catch::parseReporterSpec(reporter));
	return 0;
#endif
}

// Whether the command line only asks for lists or help, so that no test case will run.
inline bool lists_only(Catch::Session& session) {
	Catch::ConfigData& data = session.configData();
#if LAB_CATCH2_MAJOR == 2
	return data.listTests || data.listTestNamesOnly || data.listTags || data.listReporters || data.showHelp;
#else
	return data.listTests || data.listTags || data.listReporters || data.listListeners || data.showHelp;
#endif
}

} // namespace catch2_seam

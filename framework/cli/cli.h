#pragma once
// The renderer's command line (programs pathtracer_reference and pathtracer_student):
//   pathtracer_reference SCENE.json [options]        (--help lists the options and views)
// It is a function so tests can run it without starting a process.
#include "scene.h"

#include <iosfwd>
#include <string>
#include <vector>

// Runs the renderer. `args` is the whole command line as in argv: args[0] is the program name.
// Results (written files, time, speed, non-finite samples) go to `out`; "error: ..." lines,
// warnings and the progress bar go to `err`. The progress bar is drawn only if `err_is_terminal`
// and --quiet is not given.
//
// Every option and the scene are checked before rendering, so bad input writes no file.
// Returns the exit status: 0 on success, CLI_USAGE_ERROR (2) for a bad command line (an unknown
// option, a bad value, no scene: the same status as ./lab's usage errors), 1 for any other error.
// `integrator` is the program's default for --integrator (framework/cli/main.cpp).
constexpr int CLI_USAGE_ERROR = 2;
int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
            bool err_is_terminal = false, const std::string& integrator = "mixture");

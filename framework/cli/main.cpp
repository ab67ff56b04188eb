// The renderer's program: pathtracer_reference / pathtracer_student (see framework/cli/cli.h).
#include "cli.h"
#include "terminal.h"

#include <iostream>

// The reference renders with next-event estimation by default; a student's renderer with the lab's
// estimator, since NEE runs task 6's optional extension (tasks/CMakeLists.txt defines the switch).
#ifdef LAB_REFERENCE_RENDERER
constexpr const char* DEFAULT_INTEGRATOR = "nee";
#else
constexpr const char* DEFAULT_INTEGRATOR = "mixture";
#endif

int main(int argc, char** argv) {
	std::vector<std::string> args(argv, argv + argc);
	return run_cli(args, std::cout, std::cerr, stderr_is_terminal(), DEFAULT_INTEGRATOR);
}

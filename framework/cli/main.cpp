// The renderer's program: pathtracer_reference / pathtracer_student (see framework/cli.h).
#include "cli.h"
#include "terminal.h"

#include <iostream>

int main(int argc, char** argv) {
	std::vector<std::string> args(argv, argv + argc);
	return run_cli(args, std::cout, std::cerr, stderr_is_terminal());
}

#pragma once
#include <stdexcept>
#include <string>

// An error in the user's input (a scene, a mesh, an image, a command-line option). The message
// names the file, the element and what was expected; programs print it and exit non-zero.
struct Input_Error : std::runtime_error {
	using std::runtime_error::runtime_error;
};

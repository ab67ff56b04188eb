#pragma once
// Loads a JSON scene (format: scenes/README.md). Relative file names inside it are relative to the
// scene file. Throws Input_Error("<file>: <element>: <what was expected>") on bad input.
#include "json_element.h"
#include "scene.h"

#include <string>

Scene load_scene(const std::string& path);
// A scene described in code as a scene file would describe it, read as if it were the file `path`
// (e.g. a graded scene varied by a grading seed, tests/support/graded_variation.h).
Scene load_scene(const Json& description, const std::string& path);

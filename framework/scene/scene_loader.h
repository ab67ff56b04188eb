#pragma once
// Loads a JSON scene (format: scenes/README.md). Relative file names inside it are relative to the
// scene file. Throws Input_Error("<file>: <element>: <what was expected>") on bad input.
#include "scene.h"

#include <string>

Scene load_scene(const std::string& path);

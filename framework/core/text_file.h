#pragma once
#include <string>

// The whole content of a file. Throws Input_Error("<path>: ...") if it is missing, not a regular
// file, or unreadable.
std::string read_text_file(const std::string& path);

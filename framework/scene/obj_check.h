#pragma once
// The checks of an OBJ file's text that tinyobjloader does not make: it reads "v nan 0 0" or
// "v x 0 0" as 0, and turns an index before the first vertex ("f 1 2 -7" in a file of 3
// vertices) into another index before it complains. Every "v" and "vn" line must hold three
// finite numbers, and every index of an "f" line, as written, must refer to a vertex, texture
// coordinate or normal the file defines: 1 to n counting from the start of the file, or -1 to -k
// counting back from the line (k defined before it).
//
// Throws Input_Error("<path>: line <n>: ...") naming the value as written and the range expected.
#include <string>

void check_obj_text(const std::string& path, const std::string& text);

#pragma once
// Output files, written all or nothing. The bytes go to a temporary file in the same folder, which
// is renamed to the file's name only once every byte is written and the file is closed: a full
// disk never leaves a truncated file, nor destroys the one it was to replace. A name that is a
// device (e.g. a link to /dev/full) is written directly. Missing folders are created.
// Errors are Input_Error("<path>: ...") with the system's reason, e.g. "No space left on device".
#include <string>

// Checks, before a long computation, that `path` could be written: its folder exists or can be
// created, a file can be created in it, and `path` is not a folder. Leaves nothing behind (folders
// it had to create are removed again).
void check_writable(const std::string& path);

// Writes `bytes` as the whole content of `path`.
void write_file(const std::string& path, const std::string& bytes);

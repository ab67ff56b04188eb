#pragma once
// The compiler's and linker's messages in a build log, for the page: a student who saves a file
// that does not compile sees each error with its file and line, as the terminal shows it.
#include <string>
#include <vector>

struct Diagnostic {
	std::string file;     // as the compiler names it
	int line = 0, column = 0; // 0 when the message names none (a linker error)
	std::string severity; // "error", "fatal error", "warning" or "note"
	std::string message;
};

// GCC's "FILE:LINE:COLUMN: SEVERITY: MESSAGE" (and "FILE:LINE: SEVERITY: ...") lines, and the
// linker's "undefined reference to ..." lines, in the order of the log.
std::vector<Diagnostic> parse_diagnostics(const std::string& log);

// The last `lines` lines of a log: what the page shows of a long one.
std::string last_lines(const std::string& log, size_t lines);

#include "diagnostics.h"

#include <regex>
#include <sstream>

std::vector<Diagnostic> parse_diagnostics(const std::string& log) {
	static const std::regex compiler(R"(^([^:\s][^:]*):(\d+):(?:(\d+):)? (error|fatal error|warning|note): (.*)$)");
	static const std::regex linker(R"(^(?:.*: )?(undefined reference to .*|multiple definition of .*)$)");
	std::vector<Diagnostic> found;
	std::istringstream lines(log);
	std::string line;
	std::smatch m;
	while (std::getline(lines, line)) {
		if (std::regex_match(line, m, compiler)) {
			found.push_back({m[1], std::stoi(m[2]), m[3].matched ? std::stoi(m[3]) : 0, m[4], m[5]});
		} else if (std::regex_match(line, m, linker)) {
			found.push_back({"", 0, 0, "error", m[1]});
		}
	}
	return found;
}

std::string last_lines(const std::string& log, size_t lines) {
	size_t end = log.size(), start = end;
	for (size_t n = 0; start > 0; start--) {
		if (log[start - 1] == '\n' && start != end && ++n > lines) break;
	}
	return log.substr(start);
}

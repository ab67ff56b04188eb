// lab_confine: runs a program that may read only the system and the paths given, and write only
// the paths given (Landlock, landlock.h). For where bubblewrap cannot run: the compile and the link
// of a student's file (grading/bin/sandboxed).
//
//   lab_confine [--read PATH]... [--write PATH]... -- PROGRAM [ARGUMENTS]
//
// The environment is cleared but for PATH, and TMPDIR is the first --write path. Exits with 3,
// saying why, where the kernel cannot confine it.
#include "landlock.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <unistd.h>

int main(int argc, char** argv) {
	std::vector<std::string> readable = system_files(), writable;
	int i = 1;
	for (; i + 1 < argc && std::strcmp(argv[i], "--") != 0; i += 2) {
		if (std::strcmp(argv[i], "--read") == 0) readable.push_back(argv[i + 1]);
		else if (std::strcmp(argv[i], "--write") == 0) writable.push_back(argv[i + 1]);
		else break;
	}
	if (i + 1 >= argc || std::strcmp(argv[i], "--") != 0) {
		std::fprintf(stderr, "usage: lab_confine [--read PATH]... [--write PATH]... -- PROGRAM [ARGUMENTS]\n");
		return 2;
	}
	Landlock_Rules rules(readable, writable);
	if (!rules.available()) {
		std::fprintf(stderr, "lab_confine: cannot confine %s: %s\n", argv[i + 1], rules.problem().c_str());
		return 3;
	}
	std::string tmpdir = "TMPDIR=" + (writable.empty() ? std::string("/nonexistent") : writable.front());
	char* const environment[] = {const_cast<char*>("PATH=/usr/bin:/bin"), tmpdir.data(), nullptr};
	if (!rules.apply_to_self()) {
		std::perror("lab_confine: cannot apply the Landlock rules");
		return 3;
	}
	execve(argv[i + 1], argv + i + 1, environment);
	std::fprintf(stderr, "lab_confine: cannot run %s: %s\n", argv[i + 1], std::strerror(errno));
	return 127;
}

#pragma once
// A benchmark program's command line: its name and usage text, said once, for --help and for the
// errors (exit status 2, as the lab's own commands).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

struct Bench_Usage {
	const char* program;
	const char* text;

	// "PROGRAM: MESSAGE" and the usage on standard error; exit status 2.
	[[noreturn]] void error(const std::string& message) const {
		std::fprintf(stderr, "%s: %s\n\n%s", program, message.c_str(), text);
		std::exit(2);
	}

	// For -h or --help: the usage on standard output; exit status 0.
	void help_if_asked(const std::string& arg) const {
		if (arg != "-h" && arg != "--help") return;
		std::printf("%s", text);
		std::exit(0);
	}

	// The value that follows option argv[i] (i moves on to it), or an error naming the option.
	std::string value_of(int& i, int argc, char** argv) const {
		if (i + 1 >= argc) error(std::string("unknown option or missing value: '") + argv[i] + "'");
		return argv[++i];
	}

	// `value` as a whole number from `least` to 1000000 (nothing but digits), or an error naming the option.
	uint32_t whole_number(const std::string& option, const std::string& value, uint32_t least) const {
		char* end = nullptr;
		long n = std::strtol(value.c_str(), &end, 10);
		if (value.empty() || *end || n < long(least) || n > 1000000)
			error(option + " needs a whole number from " + std::to_string(least) + " to 1000000, got '" + value + "'");
		return uint32_t(n);
	}
};

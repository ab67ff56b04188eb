#pragma once
// File-system confinement by Landlock (Linux >= 5.13), for where bubblewrap cannot run: a process
// that restricts itself may afterwards open only what the rules allow, and so may every program it
// execs (the rules are inherited and can never be lifted).
//
// The rules are made in the parent (opening paths allocates) and applied in the child between fork
// and exec, where only system calls are safe: Landlock_Rules::apply_to_self().
#include <string>
#include <vector>

class Landlock_Rules {
public:
	// Read (and execute) `readable`, read and write `writable`, nothing else. Paths that do not
	// exist are skipped. available() is false where the kernel has no Landlock (or it is off).
	Landlock_Rules(const std::vector<std::string>& readable, const std::vector<std::string>& writable);
	~Landlock_Rules();
	Landlock_Rules(const Landlock_Rules&) = delete;
	Landlock_Rules& operator=(const Landlock_Rules&) = delete;

	bool available() const {
		return ruleset >= 0;
	}
	int abi() const {
		return abi_;
	}
	// Why it is not available ("" if it is).
	const std::string& problem() const {
		return problem_;
	}
	// In the child, before exec: no new privileges, then the rules. False if they could not be applied.
	bool apply_to_self() const;

private:
	int ruleset = -1;
	int abi_ = 0;
	std::string problem_;
};

// The system a program needs to start and run, read-only: /usr (and the /lib, /bin links into it),
// the dynamic loader's cache, the CPU count (/sys/devices/system/cpu) and /dev/null, /dev/zero,
// /dev/urandom.
std::vector<std::string> system_files();

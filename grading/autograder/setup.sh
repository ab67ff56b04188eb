#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image: it installs the lab's
# Debian or Ubuntu packages and builds the grading kit (the judges, the framework, the prebuilt
# reference's subjects' parts) in /autograder/source/build.
set -euo pipefail
cd "$(dirname "$0")"
[ ! -f grading/seed ] || chmod 600 grading/seed # the grader's alone, whoever the submission runs as
./lab setup
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build --parallel "$(nproc)" --target grading_kit
echo "setup.sh: the grading kit is built"
# With a grading seed, the graded scenes vary with it and the judges render their references
# (tests/support/graded_variation.h): rendered here once, by grading the shipped stubs, into
# build/grading/reference-cache (root's alone), where every submission's grading finds them.
if [ -f grading/seed ]; then
	options=(--seed @grading/seed)
	[ ! -f grading/allow-unsandboxed ] || options+=(--allow-unsandboxed)
	stubs=$(mktemp -d)
	mkdir "$stubs/none"
	KIT=build/grading/kit.env grading/bin/grade-submission "$stubs/none" --out "$stubs/graded" --records-only "${options[@]}" \
		>"$stubs/log" 2>&1 || { cat "$stubs/log"; exit 1; }
	rm -rf "$stubs"
	echo "setup.sh: the graded scenes' references for this seed are rendered"
fi

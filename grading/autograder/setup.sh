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

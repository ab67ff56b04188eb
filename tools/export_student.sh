#!/usr/bin/env bash
# The student release: writes DIR with everything students need and no reference source. The
# reference tasks ship compiled, one static archive per task in prebuilt/, so that each grader still
# links the student's task N with the reference of the other six (cmake/lab.cmake); so does the
# framework's code that would give a task away (the fast accelerator's packed triangle and box
# tests, the area lights' geometry, the NEE integrator): every lab_library, whose sources the build
# lists in shipped_compiled.txt.
#
# usage: tools/export_student.sh DIR   (./lab export DIR)
# LAB_EXPORT_BUILD_DIR: where the archives are built (default build-release-objects/).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
[ $# -eq 1 ] || { echo "usage: ./lab export DIR" >&2; exit 2; }
dest=$1
objects=${LAB_EXPORT_BUILD_DIR:-$root/build-release-objects}
jobs=$(nproc 2>/dev/null || echo 2)
if [ -e "$dest" ] && [ -n "$(ls -A "$dest")" ]; then
	echo "lab export: $dest exists and is not empty" >&2
	exit 2
fi

# The reference tasks as students will compile their own: Release, the lab's flags, and no LTO
# (LTO objects only link with the very compiler version that wrote them).
cmake -S "$root" --preset dev -B "$objects" >&2
mapfile -t libraries < <(cut -d' ' -f1 "$objects/shipped_compiled.txt" | sort -u)
mapfile -t shipped_compiled < <(cut -d' ' -f2 "$objects/shipped_compiled.txt")
cmake --build "$objects" --parallel "$jobs" --target "${libraries[@]/%/_archive}" >&2

# The tree: everything but reference/, the framework's code that ships compiled, the instructors'
# tests (stress, images, crosscheck, fuzz, export, isolation, mutants, security, class, gradescope;
# the mutants' edits quote the reference, and the grading product's own tests) and the benchmarks;
# of grading/, what ./lab grade and ./lab report run: the judge's runtime, the grade report, and the
# scripts that build a student's task file and grade it (not the instructors' scripts, rubric and
# README).
mkdir -p "$dest/tests" "$dest/prebuilt" "$dest/grading/bin"
(cd "$root" && cp -R CMakeLists.txt CMakePresets.json lab .devcontainer cmake framework tasks student scenes handouts "$dest/")
for source in "${shipped_compiled[@]}"; do rm -f "$dest/$source"; done
find "$dest/framework" -type d -empty -delete
(cd "$root/grading" && cp -R CMakeLists.txt judge report checks "$dest/grading/" &&
	cp bin/grade-task bin/compile-student bin/sandboxed "$dest/grading/bin/")
(cd "$root/tests" && cp -R CMakeLists.txt support framework task1 task2 task3 task4 task5 task6 task6_nee task7 task8 "$dest/tests/")
for library in "${libraries[@]}"; do cp "$objects/prebuilt/lib$library.a" "$dest/prebuilt/"; done

# The students' README: the "For students" section of the instructors' README.
{
	cat <<README
# PathTracer Lab

Build an end-to-end Monte Carlo path tracer in seven graded tasks (and an optional eighth). You edit
only the task files in \`student/\`; \`prebuilt/\` holds the reference solution of every task,
compiled, so that each task is graded with the reference for the others.

\`\`\`sh
./lab render-student    # installs missing Debian packages, builds, renders the Cornell box with your code
./lab grade 1           # builds and runs the grader of task 1 against your code
\`\`\`

README
	sed -n '/^## For students$/,/^## For instructors$/p' "$root/README.md" | sed '1d;$d'
} >"$dest/README.md"
echo "$dest"

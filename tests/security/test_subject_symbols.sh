#!/usr/bin/env bash
# Nothing a subject links can answer its own task's requests (label security): the framework's code
# that computes a task's graded behaviour end to end is never linked into that task's subject.
#   - the fast accelerator (framework/accel/fast/: its own triangle and box tests and traversal)
#     answers tasks 2 and 3: not in their subjects, which use the plain accelerator (task 3's
#     BVH::hit);
#   - the NEE integrator (framework/render/nee_integrator.cpp, an estimator of task 4's image)
#     answers task 4: not in task 4's subjects, which link framework/render/no_nee_integrator.cpp.
# (The area lights' geometry and the light sampling task 6 calls, shipped compiled too, compute no
# task's answer: they are the API the tasks are written against.)
# Each object a program links leaves its source file's name in the program's symbol table (a FILE
# symbol before its local symbols). For each task this lists the shipped-compiled sources (the
# build's shipped_compiled.txt: the framework's and the reference's) its subjects link, built both ways,
# by CMake (subject_taskN_student) and by the grading kit (grade-submission --link-only), and fails on
# a source that can answer the task; the reference's subject, which links them all, proves that the
# check sees them.
#   test_subject_symbols.sh REPOSITORY_ROOT KIT SUBJECTS_DIR SHIPPED_COMPILED_TXT
set -euo pipefail
root=$1 kit=$2 subjects=$3 manifest=$4
fail() { echo "subject symbols test: $*" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

fast_accelerator=(wide_bvh_build.cpp wide_bvh_traversal.cpp flat_meshes.cpp)
nee_integrator=(nee_integrator.cpp)
mapfile -t shipped_compiled < <(cut -d' ' -f2 "$manifest" | grep '\.cpp$' | xargs -n1 basename)

# The source files whose objects PROGRAM links, one per line.
sources_of() { readelf -sW "$1" | awk '$4 == "FILE" { print $8 }' | sort -u; }
links() { sources_of "$1" | grep -qxF "$2"; }

# The control: the reference's subject links every one of them.
for file in "${fast_accelerator[@]}" "${nee_integrator[@]}"; do
	links "$subjects/subject_reference" "$file" || fail "the reference's subject does not show $file: this check would see nothing"
done

# The kit's subjects of the shipped stubs, linked as grade-submission links a submission's.
mkdir "$tmp/none"
KIT=$kit "$root/grading/bin/grade-submission" "$tmp/none" --out "$tmp/graded" --link-only >"$tmp/link.log" 2>&1 ||
	{ cat "$tmp/link.log" >&2; fail "grade-submission --link-only failed"; }

for n in 1 2 3 4 5 6 7; do
	forbidden=()
	[[ $n == 2 || $n == 3 ]] && forbidden+=("${fast_accelerator[@]}")
	[[ $n == 4 ]] && forbidden+=("${nee_integrator[@]}")
	for subject in "$subjects/subject_task${n}_student" "$tmp/graded/work/task$n/subject_task$n"; do
		linked=$(sources_of "$subject" | grep -xF -f <(printf '%s\n' "${shipped_compiled[@]}") | grep -v "^task${n}_" |
			tr '\n' ' ')
		echo "subject symbols test: task $n ($subject) links, shipped compiled: $linked"
		for file in "${forbidden[@]}"; do
			! links "$subject" "$file" || fail "task $n's subject $subject links $file, which can answer task $n"
		done
	done
done
echo "subject symbols test: no subject links the framework code that can answer its own task"

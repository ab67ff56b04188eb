#!/usr/bin/env bash
# Nothing a subject links can answer its own task's requests (label security): the framework's code
# that computes a task's graded behaviour end to end is never linked into that task's subject.
#   - the fast accelerator (framework/accel/fast/: its own triangle and box tests and traversal)
#     answers tasks 2 and 3: not in their subjects, which use the plain accelerator (task 3's
#     BVH::hit);
#   - the NEE integrator (framework/render/integrators/nee_integrator.cpp, an estimator of task 4's
#     image) answers task 4: not in task 4's subjects, which have task 4's integrator alone.
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

fast_accelerator=(wide_bvh_build.cpp sah_collapse.cpp flat_meshes.cpp fast_accelerator.cpp four_wide_queries.cpp eight_wide_queries.cpp)
nee_integrator=(nee_integrator.cpp)
mapfile -t shipped_compiled < <(cut -d' ' -f2 "$manifest" | grep '\.cpp$' | xargs -n1 basename)

# The source files whose objects PROGRAM links, one per line.
sources_of() { readelf -sW "$1" | awk '$4 == "FILE" { print $8 }' | sort -u; }
links() { grep -qxF "$2" <<<"$(sources_of "$1")"; }

# The control: the reference's subject links every one of them.
for file in "${fast_accelerator[@]}" "${nee_integrator[@]}"; do
	links "$subjects/subject_reference" "$file" || fail "the reference's subject does not show $file: this check would see nothing"
done

# The kit's subjects of the shipped stubs, linked as grade-submission links a submission's.
mkdir "$tmp/none"
KIT=$kit "$root/grading/bin/grade-submission" "$tmp/none" --out "$tmp/graded" --link-only >"$tmp/link.log" 2>&1 ||
	{ cat "$tmp/link.log" >&2; fail "grade-submission --link-only failed"; }

for n in 1 2 3 4 5 6 7 8; do
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

# A subject runs the student's functions, never another copy: no input of a submitted task N's link
# (LAB_SUBJECT_LINK_N: the other tasks, the subject's main, the framework) defines one of task N's
# functions (the names its file may define, grading/checks/, and for task 3 its BVH's build and
# hit), weakly or not, where the linker could choose it over the student's.
# shellcheck source=/dev/null
source "$kit"
for n in 1 2 3 4 5 6 7 8; do
	link_var=LAB_SUBJECT_LINK_$n
	mapfile -t inputs < <(tr ' ' '\n' <<<"${!link_var}" | grep '^/')
	defined=$(nm --defined-only --format=posix "${inputs[@]}" 2>/dev/null | awk 'NF >= 2 { print $1 }' | sort -u)
	found=$(grep -xF -f "$LAB_CHECKS_DIR/task${n}_symbols.txt" <<<"$defined" || true)
	[ "$n" != 3 ] || found+=$(c++filt <<<"$defined" | grep -E '^BVH<.*>::(build|hit)\(' || true)
	[ -z "$found" ] || fail "task $n's kit link defines task $n's own functions: $(c++filt <<<"$found" | tr '\n' ' ')"
done
echo "subject symbols test: no kit link defines a function of its own task"

# W^X in the file: no segment of a subject is both writable and executable, its stack is not
# executable, and the pages mapped executable hold code alone: an executable segment starts on a
# page of its own and no other segment's bytes share its first or last page (lld without
# -z separate-code maps the read-only data before .text into .text's first page, executable).
check_segments() { # PROGRAM
	readelf -lW "$1" | awk -v program="$1" '
		function hex(text,   value, k) { # 0x... (mawk has no strtonum)
			value = 0
			for (k = 3; k <= length(text); k++) value = value * 16 + index("0123456789abcdef", tolower(substr(text, k, 1))) - 1
			return value
		}
		function page_down(x) { return x - x % 4096 }
		function page_up(x) { return page_down(x + 4095) }
		$1 == "GNU_STACK" && $0 ~ / RWE / { bad = bad " an executable stack;" }
		$1 == "LOAD" {
			n++
			offset[n] = hex($2); size[n] = hex($5)
			flags[n] = substr($0, index($0, $6) + length($6))
			executable[n] = flags[n] ~ /E/
			if (executable[n] && flags[n] ~ /W/) bad = bad " a writable and executable segment;"
		}
		END {
			for (i = 1; i <= n; i++) {
				if (!executable[i]) continue
				from = page_down(offset[i]); to = page_up(offset[i] + size[i])
				for (j = 1; j <= n; j++) {
					if (j != i && size[j] > 0 && offset[j] < to && offset[j] + size[j] > from) {
						bad = bad " other bytes in an executable page (segment " j ");"
					}
				}
			}
			if (bad != "") { print program ":" bad; exit 1 }
		}' || fail "$1 maps something executable that is not its code"
}
for n in 1 2 3 4 5 6 7 8; do
	check_segments "$subjects/subject_task${n}_student"
	check_segments "$tmp/graded/work/task$n/subject_task$n"
done
echo "subject symbols test: every subject maps only code executable, and nothing both writable and executable"

#!/usr/bin/env bash
# The student release (./lab export) in a temporary folder: it must hold no solution source (no
# reference/, no source the build lists as shipped compiled (shipped_compiled.txt: the reference's,
# the framework's lab_library sources), no line of reference code, no function of the reference or of
# those framework sources, renamed or not), and its task-1 grader must build from
# the prebuilt reference with the release's presets and fail on the shipped stub.
#
# Everything the release's text (README, handouts, ./lab help, code comments) names, the release has:
# paths, handout sections, ./lab commands and functions (tests/export/release_references.cpp), and
# that check fails on a copy with a wrong reference of each kind planted.
#
# usage: test_export.sh REPOSITORY_ROOT SOLUTION_SCAN RELEASE_REFERENCES
set -euo pipefail

root=$1
scan=$2
references=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "export test: $*" >&2; exit 1; }

LAB_EXPORT_BUILD_DIR=$tmp/objects "$root/lab" export "$tmp/release" >/dev/null 2>"$tmp/export.log" ||
	{ cat "$tmp/export.log" >&2; fail "./lab export failed"; }
release=$tmp/release

# No reference source: no reference/ folder, and no line of reference code that the stubs lack.
[ ! -e "$release/reference" ] || fail "the release has a reference/ folder"
manifest=$tmp/objects/shipped_compiled.txt
grep -q '^framework_sealed framework/scene/lights.cpp$' "$manifest" && grep -q '^integrators_beyond_task4 ' "$manifest" &&
	grep -q '^accelerator_fast framework/accel/fast/wide_bvh.h$' "$manifest" ||
	fail "$manifest does not list the framework's shipped-compiled sources: this check would see nothing"
while read -r library source; do
	[ ! -e "$release/$source" ] || fail "the release has $source, which ships compiled in prebuilt/lib$library.a"
	[ -f "$release/prebuilt/lib$library.a" ] || fail "prebuilt/lib$library.a is missing"
done <"$manifest"
# The mutants' edits quote the reference line by line (tests/mutants/README.md).
[ ! -e "$release/tests/mutants" ] || fail "the release has the instructors' mutants, tests/mutants/"
# Of grading/, what ./lab grade and ./lab report run; not the instructors' scripts, rubric or README.
for file in grading/bin/grade-submission grading/bin/grade-class grading/bin/make-autograder grading/rubric.json grading/README.md; do
	[ ! -e "$release/$file" ] || fail "the release has the instructors' $file"
done
# Code lines (not comments) of reference/ long enough to be distinctive, absent from the stubs and
# not quoted on purpose by a handout. A single line can recur by coincidence (a test oracle does
# the same thing); three in one file mean copied code.
patterns=$tmp/reference_lines
for file in "$root"/reference/*.cpp; do
	stub=$root/student/$(basename "$file")
	while IFS= read -r line; do
		trimmed=$(echo "$line" | sed 's/^[[:space:]]*//')
		[ ${#trimmed} -ge 40 ] || continue
		[[ $trimmed == //* || $trimmed == \** || $trimmed == /\** ]] && continue
		grep -qF -- "$trimmed" "$stub" && continue
		grep -rqF -- "$trimmed" "$root/handouts" && continue
		echo "$trimmed"
	done <"$file"
done | sort -u >"$patterns"
checked=$(wc -l <"$patterns")
[ "$checked" -ge 50 ] || fail "only $checked distinctive reference lines to look for: the check is too weak"
while IFS=: read -r file count; do
	[ "$count" -lt 3 ] || fail "$file has $count lines of reference code: $(grep -F -f "$patterns" "$file" | head -3)"
done < <(grep -rIcF -f "$patterns" "$release" | grep -v ':0$' || true)
echo "export test: no file of the release has 3 of the $checked distinctive reference lines"

# By function: no function of the release holds most of a function of the reference or of the
# framework code a release ships compiled, whatever its names (tests/export/solution_scan.cpp).
mapfile -t solution < <(cut -d' ' -f2 "$manifest" | grep '\.cpp$' | sed "s|^|$root/|")
mapfile -t release_sources < <(find "$release" -name '*.cpp' -o -name '*.h' | grep -v "/build/" | sort)
"$scan" --solution "${solution[@]}" --release "${release_sources[@]}" >"$tmp/scan.log" ||
	{ cat "$tmp/scan.log" >&2; fail "the release holds solution functions"; }
tail -1 "$tmp/scan.log"
# The scan must be able to fail: a copy of the reference's Triangle::hit with every name changed and
# its comments dropped and its lines rejoined is found.
sed -n '/^Trace Triangle::hit/,/^}/p' "$root/reference/task2_shapes.cpp" |
	sed -e 's|//.*||; s/\be1\b/edge_a/g; s/\be2\b/edge_b/g; s/\binv_det\b/r/g; s/\bdet\b/d/g; s/Triangle::hit/Tri::intersect/' |
	tr '\n' ' ' >"$tmp/planted.cpp"
"$scan" --solution "${solution[@]}" --release "$tmp/planted.cpp" >"$tmp/planted.log" &&
	fail "solution_scan did not find a renamed copy of Triangle::hit"
grep -q "of the solution function" "$tmp/planted.log" || fail "solution_scan failed without naming the copy"
echo "export test: solution_scan finds a renamed copy of Triangle::hit"

# What the release's text names, it has (tests/export/release_references.cpp).
"$references" "$release" >"$tmp/references.log" ||
	{ cat "$tmp/references.log" >&2; fail "the release's text names things the release does not have"; }
tail -1 "$tmp/references.log"
# The check must be able to fail: a copy of the release (hard links, and a new file for each one
# changed) with one wrong reference of each kind planted in a handout and in a framework comment.
planted=$tmp/planted_release
cp -al "$release" "$planted"
plant() { # FILE TEXT: a new copy of FILE with TEXT appended
	cat "$planted/$1" >"$planted/$1.new"
	echo "$2" >>"$planted/$1.new"
	mv "$planted/$1.new" "$planted/$1"
}
plant handouts/task1_camera.md 'See `framework/no_such_file.h`, §1.9, `./lab no-such-command` and `no_such_function(p)`.'
plant framework/api/camera.h '// planted: the details are in bench/README.md'
"$references" "$planted" >"$tmp/planted_references.log" &&
	fail "release_references passed a release with planted wrong references"
for expected in "handouts/task1_camera.md:.*framework/no_such_file.h" "handouts/task1_camera.md:.*§1.9" \
	"handouts/task1_camera.md:.*./lab no-such-command" "handouts/task1_camera.md:.*no_such_function()" \
	"framework/api/camera.h:.*bench/README.md"; do
	grep -q "$expected" "$tmp/planted_references.log" ||
		{ cat "$tmp/planted_references.log" >&2; fail "release_references did not report the planted reference '$expected'"; }
done
echo "export test: release_references reports a planted missing file, section, command, function and commented path"
# Every handout tells what to do when the student's code crashes or hangs (the README's section).
for handout in "$release"/handouts/task[1-8]_*.md; do
	n=$(basename "$handout" | sed 's/^task\([1-8]\)_.*/\1/')
	grep -qF "./lab grade $n --debug" "$handout" && grep -qF "README.md#when-it-crashes-or-hangs" "$handout" ||
		fail "$(basename "$handout") does not point to ./lab grade $n --debug and the README's \"When it crashes or hangs\""
done
echo "export test: every handout points to ./lab grade N --debug and the README's \"When it crashes or hangs\""

# The student's view: configure, build the task-1 grader (and the grade report's tool), run ctest -L task1.
cmake -S "$release" --preset release -B "$release/build" >"$tmp/configure.log" 2>&1 ||
	{ cat "$tmp/configure.log" >&2; fail "the release does not configure"; }
cmake --build "$release/build" --parallel 2 --target judge_task1 subject_task1_student grade_report >"$tmp/build.log" 2>&1 ||
	{ tail -40 "$tmp/build.log" >&2; fail "judge_task1, subject_task1_student or grade_report does not build in the release"; }
status=0
(cd "$release" && ctest --preset lab --test-dir "$release/build" -L task1) >"$tmp/ctest.log" 2>&1 || status=$?
cat "$tmp/ctest.log" | tail -15
[ "$status" -ne 0 ] || fail "ctest -L task1 passed on the shipped stub"
grep -q "tests failed out of 1$" "$tmp/ctest.log" || fail "ctest -L task1 did not run exactly one test"
grep -q "inputs: the public test cases" "$tmp/ctest.log" || fail "the output is not the task-1 judge's"
grep -Eq "test cases: *[0-9]+ \| *([0-9]+ passed \| *)?[1-9][0-9]* failed" "$tmp/ctest.log" ||
	fail "the grader did not run to its summary with failed test cases (a crash?)"
echo "export test: the release builds, and its task-1 grader fails on the stub as it should"

# The grade report's pieces work in the release: the driver ./lab report runs for each task
# (grading/bin/grade-task) has the task-1 grader record its results and images, and grade_report
# turns them into a page that shows task 1 failing.
"$release/grading/bin/grade-task" 1 --build "$release/build" --out "$tmp/report" >"$tmp/report.log" 2>&1 ||
	fail "grade-task failed in the release: $(tail -5 "$tmp/report.log")"
[ "$(cat "$tmp/report/task1.exit" 2>/dev/null)" != 0 ] ||
	fail "the task-1 grader passed on the stub, or did not run: $(tail -5 "$tmp/report/task1.log" "$tmp/report/task1.build.log" 2>/dev/null)"
"$release/build/grading/report/grade_report" "$tmp/report" >/dev/null 2>&1 || fail "grade_report failed in the release"
grep -q '<h2><span class="badge FAIL">FAIL</span> Task 1: ' "$tmp/report/index.html" ||
	fail "the release's grade report does not show task 1 failing"
[ -s "$tmp/report/task1_eye_bunny_z.png" ] || fail "the release's task-1 grader wrote no heat map for the report"
echo "export test: the release's grade report shows task 1 failing, with its images"

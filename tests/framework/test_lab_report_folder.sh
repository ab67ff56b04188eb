#!/usr/bin/env bash
# `./lab report DIR` deletes only what a report wrote (label framework):
#   (a) a folder that holds files but is not a report folder (student/, say) is refused with exit
#       status 2 and a message naming it, and nothing in it changes; so is a file given as DIR;
#   (b) a new or empty folder becomes a report folder;
#   (c) a second report removes the files of the first one and keeps the files that someone else
#       put there, even under names like a report's (task1_notes.txt).
# The graders, grade_report, the grading kit that names them and cmake are stand-ins (in a temporary
# build folder and on PATH), so the test runs ./lab's own code and grading/bin/grade-task in a
# second, without building anything.
#
# usage: test_lab_report_folder.sh REPOSITORY_ROOT
set -euo pipefail

root=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "lab report folder test: $*" >&2; exit 1; }

# Stand-ins: cmake does nothing; judge N writes task<N>.json and an image named after the run
# (so that two runs write different files); grade_report writes index.html and prints its path.
build=$tmp/build
mkdir -p "$tmp/bin" "$build/tests" "$build/grading"
touch "$build/CMakeCache.txt"
printf '#!/bin/sh\nexit 0\n' >"$tmp/bin/cmake"
cat >"$tmp/grader" <<'GRADER'
#!/bin/sh
echo '{}' >"$LAB_REPORT_DIR/task$LAB_REPORT_TASK.json"
echo image >"$LAB_REPORT_DIR/task${LAB_REPORT_TASK}_cornell_run$(cat "$LAB_TEST_RUN").png"
exit 1
GRADER
: >"$build/grading/kit.env"
for n in 1 2 3 4 5 6 7 8; do
	cp "$tmp/grader" "$build/tests/judge_task$n"
	echo "LAB_JUDGE_$n='$build/tests/judge_task$n'" >>"$build/grading/kit.env"
	echo "LAB_STUDENT_SUBJECT_$n='$build/subject_task${n}_student'" >>"$build/grading/kit.env"
done
printf '#!/bin/sh\necho page >"$1/index.html"\necho "$1/index.html"\n' >"$build/grade_report"
echo "LAB_GRADE_REPORT='$build/grade_report'" >>"$build/grading/kit.env"
chmod +x "$tmp/bin/cmake" "$build"/tests/judge_task* "$build/grade_report"

# report DIR RUN: ./lab report DIR as run number RUN; its status, stdout and stderr in $tmp/lab.*
report() {
	echo "$2" >"$tmp/run"
	local status=0
	PATH=$tmp/bin:$PATH LAB_BUILD_DIR=$build LAB_TEST_RUN=$tmp/run "$root/lab" report "$1" \
		>"$tmp/lab.out" 2>"$tmp/lab.err" || status=$?
	echo "$status" >"$tmp/lab.status"
}
listing() { (cd "$1" && find . -type f -printf '%p %s\n' | sort); }

# (a) A student's folder, and a file, are refused.
student=$tmp/student
mkdir "$student"
for file in task1_camera.cpp task2_intersect.cpp task7_env.cpp notes.txt; do echo "my work" >"$student/$file"; done
before=$(listing "$student")
report "$student" 1
[ "$(cat "$tmp/lab.status")" = 2 ] || fail "./lab report student/ exited with $(cat "$tmp/lab.status"), expected 2"
grep -qF "$student is not a report folder" "$tmp/lab.err" || fail "no message naming the folder: $(cat "$tmp/lab.err")"
[ "$(listing "$student")" = "$before" ] ||
	fail "./lab report changed a student's folder: before: $before; after: $(listing "$student")"
echo "my work" >"$tmp/a_file"
report "$tmp/a_file" 1
[ "$(cat "$tmp/lab.status")" = 2 ] || fail "./lab report FILE exited with $(cat "$tmp/lab.status"), expected 2"
[ "$(cat "$tmp/a_file")" = "my work" ] || fail "./lab report changed a file given as its folder"

# (b) A new folder and an empty one become report folders.
mkdir "$tmp/empty"
for dir in "$tmp/new/report" "$tmp/empty"; do
	report "$dir" 1
	[ "$(cat "$tmp/lab.status")" = 0 ] || fail "./lab report $dir failed: $(cat "$tmp/lab.err")"
	[ "$(tail -1 "$tmp/lab.out")" = "$dir/index.html" ] || fail "./lab report did not print the page's path"
	for file in index.html task1.json task1_cornell_run1.png task7.exit task7.log; do
		[ -f "$dir/$file" ] || fail "./lab report $dir did not write $file"
	done
done

# (c) A second report replaces the first one's files, and only those.
dir=$tmp/new/report
echo "mine" >"$dir/notes.txt"
echo "mine" >"$dir/task1_notes.txt"
report "$dir" 2
[ "$(cat "$tmp/lab.status")" = 0 ] || fail "the second ./lab report failed: $(cat "$tmp/lab.err")"
[ -f "$dir/task1_cornell_run2.png" ] || fail "the second report did not write its image"
[ ! -e "$dir/task1_cornell_run1.png" ] || fail "the second report kept the first report's image"
for file in notes.txt task1_notes.txt; do
	[ "$(cat "$dir/$file" 2>/dev/null)" = mine ] || fail "the second report removed $file, which it did not write"
done
report "$dir" 3 # the files kept are still not the report's
[ "$(cat "$dir/task1_notes.txt" 2>/dev/null)" = mine ] || fail "the third report removed task1_notes.txt"
[ ! -e "$dir/task1_cornell_run2.png" ] || fail "the third report kept the second report's image"
echo "lab report folder test: a non-report folder is refused untouched; reports replace only their own files"

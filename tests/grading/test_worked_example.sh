#!/usr/bin/env bash
# The TA's worked example (grading/README.md, "Worked example"), made and graded (label report): in
# a scratch copy of the tree, a new request (Film_Grid_Rays: Camera::generate_ray of one camera on
# a grid of film points) and a new test case of task 1 that asks it are added as a TA adds them,
# from the pieces in worked_example/:
#   a request   = 2 files: its struct in grading/judge/protocol.h (and its name in the list of
#                 requests there), its answer in grading/judge/answers/task1.h;
#   a test case = 2 files: the TEST_CASE in tests/task1/test_generate_ray.cpp, its rubric entry in
#                 grading/rubric.json.
# Then:
#   - the diff of the four edits is the one grading/README.md shows (so the README stays true);
#   - without the rubric entry the configuration stops, naming the new id; with it, it passes;
#   - ./lab grade's driver (grading/bin/grade-task) grades the scratch tree's student/ (the shipped
#     stub) and the reference's task 1 submitted as a file: the new test case is in the judge's
#     records, failed on the stub with its message and passed on the reference.
# Builds the scratch tree's task-1 judge and subject (a few minutes).
#   test_worked_example.sh REPOSITORY_ROOT OUT
set -euo pipefail
root=$1 out=$2
here=$(cd "$(dirname "$0")" && pwd)
pieces=$here/worked_example
fail() { echo "worked example test: $*" >&2; exit 1; }
rm -rf "$out"
mkdir -p "$out"
scratch=$out/tree
mkdir "$scratch"
tar -C "$root" --exclude=./.git --exclude='./build*' --exclude=./out --exclude=./report --exclude=node_modules -cf - . |
	tar -C "$scratch" -xf -
original=$out/original
mkdir -p "$original"
edited=(grading/judge/protocol.h grading/judge/answers/task1.h tests/task1/test_generate_ray.cpp grading/rubric.json)
for file in "${edited[@]}"; do
	mkdir -p "$original/$(dirname "$file")"
	cp "$scratch/$file" "$original/$file"
done

# insert_at before|after FILE LINE PIECE: PIECE's text before (after) the first line of FILE that is
# exactly LINE.
insert_at() {
	local where=$1 file=$scratch/$2 line=$3 piece=$4
	grep -qxF -- "$line" "$file" || fail "$2 has no line '$line'"
	awk -v line="$line" -v piece="$piece" -v where="$where" '
		BEGIN { while ((getline text < piece) > 0) body = body text "\n" }
		$0 == line && !done && where == "after" { print; printf "%s", body; done = 1; next }
		$0 == line && !done { printf "%s", body; done = 1 }
		{ print }' "$file" >"$file.new"
	mv "$file.new" "$file"
}
printf '\tFilm_Grid_Rays,\n' >"$out/list_entry.txt"

# The request: its struct and its place in the list (protocol.h), its answer (answers/task1.h).
insert_at before grading/judge/protocol.h "// ---- Task 2 ----" "$pieces/request.h"
insert_at after grading/judge/protocol.h "$(printf '\tGenerate_Rays,')" "$out/list_entry.txt"
insert_at before grading/judge/answers/task1.h "} // namespace" "$pieces/answer.h"
# The test case, at the end of a task-1 file.
cat "$pieces/test_case.cpp" >>"$scratch/tests/task1/test_generate_ray.cpp"

# Without its rubric entry, the configuration names the new id.
build=$scratch/build
if cmake -S "$scratch" --preset dev -B "$build" >"$out/configure_without_entry.log" 2>&1; then
	fail "the configuration passed a test case that the rubric does not have"
fi
grep -q "t1.ray.grid-origin" "$out/configure_without_entry.log" ||
	fail "the configuration failed without naming t1.ray.grid-origin: $(tail -5 "$out/configure_without_entry.log")"
echo "worked example test: without its rubric entry, the configuration stops and names t1.ray.grid-origin"
# One rubric entry, at the start of task 1's test cases.
insert_at after grading/rubric.json "$(printf '\t\t\t"test_cases": [')" "$pieces/rubric_entry.json"
cmake -S "$scratch" --preset dev -B "$build" >"$out/configure.log" 2>&1 ||
	fail "the configuration failed with the rubric entry: $(tail -5 "$out/configure.log")"

# The edits: four files, two per addition, and the diff grading/README.md shows.
: >"$out/worked_example.diff"
for file in "${edited[@]}"; do
	diff -u --label "a/$file" --label "b/$file" "$original/$file" "$scratch/$file" >>"$out/worked_example.diff" &&
		fail "$file was not edited"
done
changed=$(grep -c '^+++ ' "$out/worked_example.diff")
[ "$changed" = 4 ] || fail "the example edits $changed files, expected 4"
awk '/^<!-- worked example diff: begin/ { inside = 1; next } /^<!-- worked example diff: end/ { inside = 0 }
	inside && !/^```/' "$root/grading/README.md" >"$out/readme.diff"
cmp -s "$out/worked_example.diff" "$out/readme.diff" ||
	fail "grading/README.md's worked example differs from the edits made here (diff $out/readme.diff $out/worked_example.diff):
$(diff "$out/readme.diff" "$out/worked_example.diff" | head -20)"
echo "worked example test: a request and a test case in 4 files ($(grep -c '^@@' "$out/worked_example.diff") hunks), as grading/README.md shows"

# Graded by the driver: the stub (./lab grade 1 in the scratch tree) and the reference's file.
"$scratch/grading/bin/grade-task" 1 --build "$build" --out "$out/stub" >"$out/stub.log" 2>&1 || fail "grade-task failed: $(tail -5 "$out/stub.log")"
[ -f "$out/stub/task1.json" ] || fail "grading the stub left no records: $(tail -20 "$out/stub/task1.build.log" 2>/dev/null)"
KIT=$build/grading/kit.env "$scratch/grading/bin/grade-task" 1 --file "$scratch/reference/task1_camera.cpp" --work "$out/work" \
	--out "$out/reference" >"$out/reference.log" 2>&1 || fail "grade-task --file failed: $(tail -5 "$out/reference.log")"
[ -f "$out/reference/task1.json" ] || fail "grading the reference left no records: $(tail -20 "$out/reference/task1.build.log" 2>/dev/null)"
# verdict RECORDS: the new test case's "passed" value in the judge's records.
verdict() {
	tr -d '\n\t' <"$1" | grep -o '"id": *"t1.ray.grid-origin"[^{]*"passed": *[a-z]*' | grep -o '[a-z]*$' ||
		fail "$1 has no test case t1.ray.grid-origin"
}
[ "$(verdict "$out/stub/task1.json")" = false ] || fail "the new test case passed on the stub"
grep -qF "every ray starts at the camera's position (3, -2, 5)" "$out/stub/task1.json" ||
	fail "the stub's records do not give the new test case's message"
[ "$(verdict "$out/reference/task1.json")" = true ] || fail "the new test case failed on the reference"
echo "worked example test: t1.ray.grid-origin recorded as failed on the stub (with its message) and passed on the reference"

#!/usr/bin/env bash
# The configuration's check of test-case ids (label report): cmake/test_case_ids.cmake, in script
# mode, on a small lab-shaped fixture (a judge's source in its tests/task1/, and its rubric):
#   (a) judges and rubric that agree pass;
#   (b) a TEST_CASE whose id the rubric lacks stops it, naming the file, the line and the id, and
#       saying what to run (`rubric --update` in ./lab);
#   (c) so does an id of the rubric that no TEST_CASE has, a TEST_CASE without an id tag (also one
#       whose title spans two lines) and two TEST_CASEs with the same id.
#
# usage: test_case_ids_check.sh REPOSITORY_ROOT CMAKE
set -euo pipefail

root=$1
cmake=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "test-case ids check test: $*" >&2; exit 1; }

# fixture RUBRIC_IDS: the fixture's judge (three test cases, ids t1.fixture.one and .two on lines 5
# and 8, the third's title on two lines) and a rubric of task 1 with the ids RUBRIC_IDS.
fixture() {
	rm -rf "$tmp/lab"
	mkdir -p "$tmp/lab/tests/task1" "$tmp/lab/grading"
	cat >"$tmp/lab/tests/task1/test_fixture.cpp" <<'CPP'
// A judge's source, for the check. TEST_CASE("not a test case", "in a comment") {
#include <catch2/catch.hpp>

// Line 5 is the first TEST_CASE.
TEST_CASE("one: a title with [brackets; and a semicolon", "[fn:one][id:t1.fixture.one]") {
}

TEST_CASE("two", "[id:t1.fixture.two]") {
}

	TEST_CASE("three: a title on "
	          "two lines", "[estimate][id:t1.fixture.three]") {
}
CPP
	local cases='' id
	for id in "$@"; do
		cases+="${cases:+, }{\"id\": \"$id\", \"title\": \"informational\", \"weight\": 1}"
	done
	echo "{\"tasks\": [{\"task\": 1, \"points\": 5, \"test_cases\": [$cases]}]}" >"$tmp/lab/grading/rubric.json"
}

# check NAME: runs the check on the fixture; its output in $tmp/NAME.out, its status in $status.
check() {
	status=0
	"$cmake" -DROOT="$tmp/lab" -DRUBRIC="$tmp/lab/grading/rubric.json" -P "$root/cmake/test_case_ids.cmake" \
		>"$tmp/$1.out" 2>&1 || status=$?
}

# stops NAME TEXT...: the check of NAME failed, and its message has each TEXT.
stops() {
	local name=$1 text
	shift
	[ "$status" -ne 0 ] || fail "$name: the check passed (status 0): $(cat "$tmp/$name.out")"
	for text in "$@"; do
		grep -qF -- "$text" "$tmp/$name.out" || fail "$name: the message lacks \"$text\": $(cat "$tmp/$name.out")"
	done
}

# (a) Judges and rubric agree: it passes, silently.
fixture t1.fixture.one t1.fixture.two t1.fixture.three
check agree
[ "$status" -eq 0 ] || fail "judges and rubric that agree were refused: $(cat "$tmp/agree.out")"
[ ! -s "$tmp/agree.out" ] || fail "judges and rubric that agree gave a message: $(cat "$tmp/agree.out")"

# (b) The rubric lacks the id of a TEST_CASE (line 8).
fixture t1.fixture.one t1.fixture.three
check missing
stops missing "tests/task1/test_fixture.cpp:8: the id t1.fixture.two is not in grading/rubric.json" \
	"./lab rubric --update"

# (c) The rubric has an id that no TEST_CASE has.
fixture t1.fixture.one t1.fixture.two t1.fixture.three t1.fixture.gone
check unknown
stops unknown "grading/rubric.json: task 1 has the id t1.fixture.gone, which no TEST_CASE of tests/task1/ has" \
	"./lab rubric --update"

# A TEST_CASE without an id tag (line 8), and one whose title spans two lines (line 11).
fixture t1.fixture.one t1.fixture.two t1.fixture.three
sed -i 's/"\[id:t1.fixture.two\]"/"[fn:two]"/; s/\[estimate\]\[id:t1.fixture.three\]/[estimate]/' \
	"$tmp/lab/tests/task1/test_fixture.cpp"
check untagged
stops untagged "tests/task1/test_fixture.cpp:8: a TEST_CASE without an id tag: add [id:t1.<area>.<name>]" \
	"tests/task1/test_fixture.cpp:11: a TEST_CASE without an id tag"

# Two TEST_CASEs with the same id.
fixture t1.fixture.one t1.fixture.two t1.fixture.three
sed -i 's/\[id:t1.fixture.two\]/[id:t1.fixture.one]/' "$tmp/lab/tests/task1/test_fixture.cpp"
check duplicate
stops duplicate "tests/task1/test_fixture.cpp:8: the id t1.fixture.one is already the id of the TEST_CASE at" \
	"tests/task1/test_fixture.cpp:5"

echo "test-case ids check test: agreeing judges and rubric pass; a missing id, an unknown id, a TEST_CASE" \
	"without an id and a duplicate id stop the configuration with file, line and id"

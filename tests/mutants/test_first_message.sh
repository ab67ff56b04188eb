#!/usr/bin/env bash
# The first message names the mistake (issue 20, items 8-12): grades one mutant with its task's judge
# and checks what a student sees first.
#   test_first_message.sh JUDGE SUBJECT FIRST [SCREEN_HAS] [NEVER_SAYS]
# FIRST: how the name of the first failing test case begins (its own function's test case, not one
# that merely uses the function); SCREEN_HAS: text the first screen (40 lines) must hold; NEVER_SAYS:
# text the whole output must not hold (a false message); "-" or nothing: no check. The run must end
# with the summary, one line per failed test case.
set -euo pipefail
judge=$1 subject=$2 first=$3 screen_has=${4:--} never_says=${5:--}
[ "$screen_has" != - ] || screen_has=
[ "$never_says" != - ] || never_says=
fail() { echo "first-message test: $*" >&2; exit 1; }
output=$("$judge" --subject "$subject" 2>&1) && fail "the judge passed $subject"
# A failing test case's first line: "FAIL  " and its name (grading/judge/lab_reporter.cpp).
name=$(sed -n 's/^FAIL  //p' <<<"$output" | head -1)
[[ $name == "$first"* ]] ||
	fail "the first failing test case is '$name'; expected one whose name begins with '$first'"
screen=$(head -40 <<<"$output")
if [ -n "$screen_has" ]; then
	grep -qF -- "$screen_has" <<<"$screen" || fail "the first 40 lines do not say '$screen_has':
$screen"
fi
if [ -n "$never_says" ]; then
	! grep -qF -- "$never_says" <<<"$output" || fail "the output says '$never_says', which is false for this mistake"
fi
grep -qE '^[0-9]+ of [0-9]+ test cases fail:$' <<<"$output" || fail "no summary of the failed test cases at the end"
failed=$(grep -oE '^test cases: *[0-9]+ \| *[0-9]+ passed \| *[0-9]+ failed' <<<"$output" | grep -oE '[0-9]+ failed' | grep -oE '[0-9]+')
lines=$(sed -n '/^[0-9]* of [0-9]* test cases fail:$/,$p' <<<"$output" | grep -cE '^  x ' || true)
[ "$lines" -eq "$failed" ] || fail "the summary lists $lines test cases, but $failed failed"
echo "first-message test: the first failing test case is '$name'; $failed failed, each summarized in one line"

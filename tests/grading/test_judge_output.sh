#!/usr/bin/env bash
# A grader on the shipped stubs, as a student reads it (label stubcheck, one per grader): the judge
# fails, runs to its count line ("test cases: N | ... failed"), and its first two lines are the first
# failed test case ("FAIL  " and its title) and that test case's message; nothing of Catch2's own
# report (a check's file:line, "FAILED:", the checked expression "with expansion") is shown
# (grading/judge/lab_reporter.cpp). --details: with LAB_GRADE_DETAILS=1 the same run shows where
# each check is, for instructors.
#   test_judge_output.sh JUDGE SUBJECT [--details]
set -uo pipefail
judge=$1 subject=$2 details=${3:-}
fail() { echo "judge output test: $*" >&2; printf '%s\n' "$output" | head -40 >&2; exit 1; }
if [ "$details" = --details ]; then
	output=$(LAB_GRADE_DETAILS=1 "$judge" --subject "$subject" 2>&1)
else
	output=$("$judge" --subject "$subject" 2>&1)
fi
status=$?
[ "$status" -ne 0 ] || fail "the judge passed the stub (exit status 0)"
grep -qE '^test cases: *[0-9]+ \|( *[0-9]+ passed \|)? *[1-9][0-9]* failed$' <<<"$output" ||
	fail "the judge did not run to its count line"
first=$(sed -n 1p <<<"$output") second=$(sed -n 2p <<<"$output")
[[ $first == "FAIL  "?* ]] || fail "the first line is not the first failed test case: '$first'"
[[ $second == "      "[![:space:]]* ]] || fail "the second line is not that test case's message: '$second'"
where='(^|[ (])(tests|grading)/[^ :]+\.(cpp|h):[0-9]+'
if [ "$details" = --details ]; then
	grep -qE "$where: " <<<"$output" || fail "LAB_GRADE_DETAILS=1 shows no check's file and line"
	echo "judge output test: with LAB_GRADE_DETAILS=1: $(grep -m1 -oE "$where: [^)]*" <<<"$output")"
	exit 0
fi
noise=$(grep -nE "$where|FAILED:|with expansion:|^-{20,}$|^\.{20,}$" <<<"$output" | head -3)
[ -z "$noise" ] || fail "the output shows Catch2's own report: $noise"
echo "judge output test: $(grep -m1 '^test cases:' <<<"$output"); it begins:"
head -2 <<<"$output" | cut -c1-160

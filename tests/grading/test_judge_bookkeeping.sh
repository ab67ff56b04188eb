#!/usr/bin/env bash
# The judge's bookkeeping of the running test case (grading/judge/judge.h), on the fixture judge of
# judge_bookkeeping.cpp: secret draws per test case, and a test case whose statistical checks differ
# from its [statistical:N] named, with exit status 4, while one that failed is not.
#
# usage: test_judge_bookkeeping.sh JUDGE SUBJECT
set -euo pipefail
judge=$1 subject=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

failures=0
expect() { # expect WHAT COMMAND...: a check, named
	local what=$1
	shift
	if "$@"; then echo "ok: $what"; else echo "FAILED: $what" >&2; failures=$((failures + 1)); fi
}

for seed in "" 17; do
	status=0
	"$judge" --subject "$subject" --sandbox none ${seed:+--seed "$seed"} >"$out/stdout" 2>"$out/stderr" || status=$?
	run="the judge${seed:+ with --seed $seed}"
	expect "$run exits with status 4 (a miscount), got $status" test "$status" -eq 4
	expect "$run names the test case that miscounts" \
		grep -qF "'a test case that miscounts' declares [statistical:2] but made 3 statistical checks" "$out/stderr"
	expect "$run names nothing else" test "$(grep -c 'miscounts:' "$out/stderr")" -eq 1
	expect "$run passes the draws' test cases" bash -c "! grep -q 'secret draws' '$out/stdout'"
done
if [ "$failures" -ne 0 ]; then
	echo "--- the last run's output:" >&2
	cat "$out/stdout" "$out/stderr" >&2
	exit 1
fi

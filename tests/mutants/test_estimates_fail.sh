#!/usr/bin/env bash
# Noise and fireflies earn nothing (issue 27 §1): grades one mutant with its task's judge and checks
# that EVERY test case tagged [estimate] failed, not merely that the judge failed somewhere. [estimate]
# marks the test cases that judge an estimate's value statistically: furnaces, closed forms and the
# reference image (tests/support/film_statistics.h, sample_moments.h, image_compare.h).
#   test_estimates_fail.sh JUDGE SUBJECT [UNREACHED]
# UNREACHED: the name of one [estimate] test case that never runs the function the mutant gets
# wrong (e.g. task 7's Env_Constant render runs only Samplers::Sphere::Uniform): it must pass, every
# other must fail.
set -euo pipefail
judge=$1 subject=$2 unreached=${3:-}
fail() { echo "estimates test: $*" >&2; exit 1; }
names=$({ "$judge" --list-test-names-only "[estimate]" || true; } | sed "/^$/d")  # Catch2 exits with the count
expected=$(grep -c . <<<"$names" || true)
[ "$expected" -gt 0 ] || fail "$judge has no test case tagged [estimate]"
output=$("$judge" --subject "$subject" "[estimate]" 2>&1) && fail "the judge passed $subject"
totals=$(grep -E '^test cases:' <<<"$output" | tail -1)
[ -n "$totals" ] || fail "the judge did not run to its summary:
$(tail -20 <<<"$output")"
ran=$(grep -oE '^test cases: *[0-9]+' <<<"$totals" | grep -oE '[0-9]+$')
passed=$(grep -oE '[0-9]+ passed' <<<"$totals" | grep -oE '[0-9]+' || echo 0)
[ "$ran" -eq "$expected" ] || fail "$ran test cases ran, $expected are tagged [estimate]"
failed_names=$(sed -n '/^[0-9]* of [0-9]* test cases fail:$/,$p' <<<"$output" | grep -E '^  x ' | grep -v '^  x := ' |
	sed 's/^  x //')
passing=$(grep -vxF -f <(printf '%s\n' "$failed_names") <<<"$names" || true)
if [ -n "$unreached" ]; then
	grep -qxF -- "$unreached" <<<"$names" || fail "no [estimate] test case is named '$unreached'"
	[ "$passing" = "$unreached" ] || fail "expected exactly '$unreached' to pass $subject; these passed:
$passing"
	echo "estimates test: $((ran - 1)) of $ran [estimate] test cases failed $(basename "$subject"); the one that does not run its mistake passed"
	exit 0
fi
[ "$passed" -eq 0 ] || fail "$passed of $ran [estimate] test cases passed $subject:
$passing"
echo "estimates test: all $ran [estimate] test cases failed $(basename "$subject")"

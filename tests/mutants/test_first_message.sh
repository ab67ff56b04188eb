#!/usr/bin/env bash
# The first message names the mistake (issue 20, items 8-12; issue 40, item 3): grades one mutant
# with its task's judge and checks what a student sees first.
#   test_first_message.sh JUDGE SUBJECT FIRST [SCREEN_HAS] [NEVER_SAYS]
#   test_first_message.sh JUDGE SUBJECT --mutant FILE.mutant
# FIRST: how the name of the first failing test case begins (its own function's test case, not one
# that merely uses the function); SCREEN_HAS: text the first screen (40 lines) must hold; NEVER_SAYS:
# text the whole output must not hold (a false message); "-" or nothing: no check. The run must end
# with the summary, one line per failed test case.
# With --mutant, the expectations come from the mutant's header (tests/mutants/README.md):
#   first: how the first failing test case's name begins
#   says: text the first screen must hold (one line each; at least one naming the handout section,
#         and one naming the function to fix)
#   never: text the whole output must not hold (any number of lines)
set -euo pipefail
judge=$1 subject=$2
fail() { echo "first-message test: $*" >&2; exit 1; }
says=() nevers=()
if [ "${3:-}" = --mutant ]; then
	mutant=$4
	header=$(sed '/^find:$/,$d' "$mutant")
	first=$(sed -n 's/^first: //p' <<<"$header")
	mapfile -t says < <(sed -n 's/^says: //p' <<<"$header")
	mapfile -t nevers < <(sed -n 's/^never: //p' <<<"$header")
	[ -n "$first" ] || fail "$mutant: its header has no line 'first: <how the first failing test case's name begins>'"
	grep -q '§' <<<"${says[*]}" ||
		fail "$mutant: its header has no line 'says: §N.M' (the handout section the first message must name)"
	[ ${#says[@]} -ge 2 ] || fail "$mutant: its header needs a line 'says: <the function to fix>' besides the section"
else
	first=$3
	[ "${4:--}" = - ] || says=("$4")
	[ "${5:--}" = - ] || nevers=("$5")
fi
output=$("$judge" --subject "$subject" 2>&1) && fail "the judge passed $subject"
# A failing test case's first line: "FAIL  " and its name (grading/judge/lab_reporter.cpp).
name=$(sed -n '/^FAIL  /{s///p;q}' <<<"$output")
[[ $name == "$first"* ]] ||
	fail "the first failing test case is '$name'; expected one whose name begins with '$first'"
# The first screen, with Catch2's wrapping undone: it breaks lines at spaces and after some
# punctuation ("§4." / "2"), so spaces are ignored when comparing.
screen=$(head -40 <<<"$output" | tr -d ' \n')
for text in "${says[@]}"; do
	grep -qF -- "${text// /}" <<<"$screen" || fail "the first 40 lines do not say '$text':
$(head -40 <<<"$output")"
done
for text in "${nevers[@]}"; do
	! grep -qF -- "$text" <<<"$output" || fail "the output says '$text', which is false for this mistake"
done
grep -qE '^[0-9]+ of [0-9]+ test cases fail:$' <<<"$output" || fail "no summary of the failed test cases at the end"
failed=$(grep -oE '^test cases: *[0-9]+ \| *[0-9]+ passed \| *[0-9]+ failed' <<<"$output" | grep -oE '[0-9]+ failed' | grep -oE '[0-9]+')
lines=$(sed -n '/^[0-9]* of [0-9]* test cases fail:$/,$p' <<<"$output" | grep -cE '^  x ' || true)
[ "$lines" -eq "$failed" ] || fail "the summary lists $lines test cases, but $failed failed"
echo "first-message test: the first failing test case is '$name'; $failed failed, each summarized in one line"
# What ctest's PASS_REGULAR_EXPRESSION of a mutant test looks for: the judge failed it.
grep -E '^test cases: ' <<<"$output"

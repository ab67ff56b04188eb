#!/usr/bin/env bash
# Grades the correct variants of one task (tests/variants/) under grading seeds: every variant must
# pass, failing no more seeds than the grader's stated false-fail rate explains.
#   grade_variants.sh JUDGE FIRST COUNT SUBJECT...
# Seeds FIRST ... FIRST + COUNT - 1 are the outer loop and the variants the inner one, so that what a
# judge computes once per grading seed (a graded scene and its reference, drawn from the seed) is
# computed for the first variant and reused by the others.
#
# The verdict. A grader's false-fail rate is at most ALPHA = 0.01 per run (README, "How a grade is
# decided"; tools/false-fail-rate), so a correct variant fails Binomial(COUNT, <= ALPHA) of the seeds.
# It passes here while its failing seeds stay below the smallest k with P(Binomial(COUNT, ALPHA) >= k)
# <= 0.001: at 100 seeds at most 5 may fail (P(>= 6) = 5e-4), at 3 seeds at most 1 (P(>= 2) = 3e-4).
# A grader bug that fails a correct variant on some kind of input fails far more seeds than that;
# each failing test case is listed with its seeds, and the first failing run's message is shown.
set -uo pipefail
[ $# -ge 4 ] || { echo "usage: grade_variants.sh JUDGE FIRST COUNT SUBJECT..." >&2; exit 2; }
judge=$1 first=$2 count=$3
shift 3
subjects=("$@")
ALPHA=0.01 LEVEL=0.001

# The largest number of failing seeds, of COUNT, still consistent with ALPHA at LEVEL.
allowed=$(awk -v n="$count" -v p="$ALPHA" -v level="$LEVEL" 'BEGIN {
	term = (1 - p) ^ n; cdf = term # P(X = 0), then P(X <= k)
	for (k = 0; k < n && 1 - cdf > level; k++) { term *= (n - k) / (k + 1) * p / (1 - p); cdf += term }
	print k }')

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
start=$SECONDS
for ((seed = first; seed < first + count; seed++)); do
	for subject in "${subjects[@]}"; do
		variant=$(basename "$subject")
		output=$("$judge" --subject "$subject" --seed "$seed" 2>&1) && continue
		echo "$seed" >>"$scratch/$variant.seeds"
		# The judge's summary lists each failed test case as "  x NAME".
		names=$(grep -E '^  x ' <<<"$output" | sed 's/^  x //' || true)
		[ -n "$names" ] || names="(no summary: the judge did not finish)"
		while IFS= read -r name; do echo "$name	$seed" >>"$scratch/$variant.cases"; done <<<"$names"
		[ -f "$scratch/$variant.first" ] || head -60 <<<"$output" >"$scratch/$variant.first"
	done
done

status=0
echo "$(basename "$judge"): ${#subjects[@]} correct variants, seeds $first ... $((first + count - 1)), $((SECONDS - start)) s;" \
	"each may fail at most $allowed of $count seeds (alpha $ALPHA per run, level $LEVEL)"
for subject in "${subjects[@]}"; do
	variant=$(basename "$subject")
	failed=0
	[ -f "$scratch/$variant.seeds" ] && failed=$(wc -l <"$scratch/$variant.seeds")
	verdict=ok
	if [ "$failed" -gt "$allowed" ]; then
		verdict="FAILED: more failing seeds than alpha explains, a bug of the grader"
		status=1
	fi
	echo "  $variant: $failed of $count seeds failed ($verdict)"
	[ "$failed" -gt 0 ] || continue
	# Per test case: how many seeds failed it, and which.
	sort "$scratch/$variant.cases" | awk -F '\t' '{ n[$1]++; s[$1] = s[$1] " " $2 } END { for (c in n) printf "    %d x %s (seeds%s)\n", n[c], c, s[c] }'
	if [ "$verdict" != ok ]; then
		echo "    the first failing run said:"
		sed 's/^/      | /' "$scratch/$variant.first"
	fi
done
exit $status

#!/usr/bin/env bash
# Grades the correct variants of one task (tests/variants/) under grading seeds: every variant must
# pass, failing no more seeds than the grader's stated false-fail rate explains.
#   grade_variants.sh JUDGE FIRST COUNT SUBJECT...
# Seeds FIRST ... FIRST + COUNT - 1 are the outer loop and the variants the inner one, so that
# whatever the judges keep per grading seed (a graded scene's reference rendered under the seed) is
# made for a seed's first variant, which runs alone, and found by the others. A judge run waits for
# its sandboxed subjects much of the time, so up to JOBS runs (default 3) go at once.
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
# Under a grading seed the judges vary each graded scene and render its reference (a minute or so,
# tests/support/graded_variation.h): here LAB_SCENE_VARIATIONS (default 4) varied scenes serve every
# seed (grading/judge/judge.h, Secret::graded_scene), their references kept in the build's reference cache,
# where grade-submission keeps them too (LAB_REFERENCE_CACHE).
export LAB_SCENE_VARIATIONS=${LAB_SCENE_VARIATIONS:-4}
export LAB_REFERENCE_CACHE=${LAB_REFERENCE_CACHE:-$(dirname "$(dirname "$judge")")/grading/reference-cache}
# One run: its failures in $scratch/<variant>.<seed>.cases ("NAME<TAB>SEED" lines) and its output's
# first lines in $scratch/<variant>.<seed>.first.
grade_one() {
	local judge=$1 seed=$2 subject=$3 scratch=$4 variant output names
	variant=$(basename "$subject")
	output=$("$judge" --subject "$subject" --seed "$seed" 2>&1) && return 0
	# The judge's summary lists each failed test case as "  x NAME".
	names=$(grep -E '^  x ' <<<"$output" | grep -v '^  x := ' | sed 's/^  x //' || true)
	[ -n "$names" ] || names="(no summary: the judge did not finish)"
	while IFS= read -r name; do printf '%s\t%s\n' "$name" "$seed"; done <<<"$names" >"$scratch/$variant.$seed.cases"
	head -60 <<<"$output" >"$scratch/$variant.$seed.first"
}
start=$SECONDS
jobs=${JOBS:-3}
for ((seed = first; seed < first + count; seed++)); do
	# A seed's first variant alone (it makes what the judges keep per seed), then the others, at most
	# $jobs runs at a time, while the next seed's first variant starts.
	for ((i = 0; i < ${#subjects[@]}; i++)); do
		while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n; done
		if [ "$i" -eq 0 ]; then
			grade_one "$judge" "$seed" "${subjects[i]}" "$scratch"
		else
			grade_one "$judge" "$seed" "${subjects[i]}" "$scratch" &
		fi
	done
done
wait

status=0
echo "$(basename "$judge"): ${#subjects[@]} correct variants, seeds $first ... $((first + count - 1)), $((SECONDS - start)) s;" \
	"each may fail at most $allowed of $count seeds (alpha $ALPHA per run, level $LEVEL)"
for subject in "${subjects[@]}"; do
	variant=$(basename "$subject")
	failed=$(find "$scratch" -name "$variant.*.cases" | wc -l)
	verdict=ok
	if [ "$failed" -gt "$allowed" ]; then
		verdict="FAILED: more failing seeds than alpha explains, a bug of the grader"
		status=1
	fi
	echo "  $variant: $failed of $count seeds failed ($verdict)"
	[ "$failed" -gt 0 ] || continue
	# Per test case: how many seeds failed it, and which.
	cat "$scratch/$variant".*.cases | sort -t "$(printf '\t')" -k2n |
		awk -F '\t' '{ n[$1]++; s[$1] = s[$1] " " $2 } END { for (c in n) printf "    %d x %s (seeds%s)\n", n[c], c, s[c] }'
	if [ "$verdict" != ok ]; then
		echo "    the first failing run said:"
		first_run=$(ls "$scratch/$variant".*.first | sort -t . -k2n | head -1)
		sed 's/^/      | /' "$first_run"
	fi
done
exit $status

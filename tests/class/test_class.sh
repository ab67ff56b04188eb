#!/usr/bin/env bash
# The class on one machine (label class): the synthetic class (make_class.sh, small or full) graded
# by ./lab grade-class with two workers must score as expected (check_gradebook.sh); a rerun resumes
# (nothing is graded again, the gradebook is the same); a submission graded again gets the same
# scores and messages. Leaves the class and its gradebook (OUT/gradebook.csv) for the GNU parallel
# and Slurm tests (the small class's: ctest fixture "class_graded").
#   test_class.sh REPOSITORY_ROOT KIT OUT small|full MUTANTS
# MUTANTS: the mutants' sources, made at configure time (BUILD/mutants, tests/mutants/README.md).
set -euo pipefail
root=$1 kit=$2 out=$3 size=$4 mutants=$5
here=$(cd "$(dirname "$0")" && pwd)
fail() { echo "class test: $*" >&2; exit 1; }
rm -rf "$out"
mkdir -p "$out"
bash "$here/make_class.sh" "$root" "$out/class" "$size" "$mutants"
minimum=4
[ "$size" = small ] || minimum=20
export KIT=$kit

start=$SECONDS
"$root/grading/bin/grade-class" "$out/class/submissions" --out "$out/graded" --jobs 2 >"$out/grade-class.log" 2>&1 ||
	{ tail -20 "$out/grade-class.log" >&2; fail "grade-class failed"; }
seconds=$((SECONDS - start))
count=$(find "$out/class/submissions" -mindepth 1 -maxdepth 1 -type d | wc -l)
echo "class test: $count submissions graded in $seconds s with 2 workers ($(awk -v s="$seconds" -v n="$count" 'BEGIN { printf "%.1f", 2 * s / n }') s of a worker each)"
bash "$here/check_gradebook.sh" "$root/grading/rubric.json" "$out/class/expected.csv" "$out/graded/gradebook.csv" "$minimum"
cp "$out/graded/gradebook.csv" "$out/gradebook.csv"

# A rerun resumes: nothing to grade, the same gradebook. The full class's (./lab acceptance, which
# installs the similarity report's npm packages) passes --similarity: the similarity report beside
# it, where the task-4 mistake (the reference but for one line) is marked as the reference's.
similarity=()
[ "$size" = small ] || similarity=(--similarity)
"$root/grading/bin/grade-class" "$out/class/submissions" --out "$out/graded" --jobs 2 "${similarity[@]}" >"$out/rerun.log" 2>&1 ||
	{ tail -5 "$out/rerun.log" >&2; fail "the rerun of grade-class failed"; }
cmp -s "$out/gradebook.csv" "$out/graded/gradebook.csv" || fail "the rerun changed the gradebook"
[ -z "$(find "$out/graded/submissions" -newer "$out/gradebook.csv" -name results.json)" ] ||
	fail "the rerun graded finished submissions again"
if [ "$size" != small ]; then
	grep -q '^4,mistake_task4_no_offset,reference,reference,[0-9.]*,1,' "$out/graded/similarity/similarity.csv" ||
		fail "grade-class --similarity: $out/graded/similarity/similarity.csv does not mark mistake_task4_no_offset's task 4 as the reference's"
fi

# The same submission and seed give the same scores and messages: regrade one and compare.
id=mistake_task4_no_offset # in both classes
strip_time() { grep -v '"execution_time"' "$1"; }
strip_time "$out/graded/submissions/$id/results.json" >"$out/first.json"
"$root/grading/bin/grade-submission" "$out/class/submissions/$id" --out "$out/graded/submissions/$id" >/dev/null 2>&1 ||
	fail "grading $id again failed"
strip_time "$out/graded/submissions/$id/results.json" >"$out/second.json"
cmp -s "$out/first.json" "$out/second.json" || { diff "$out/first.json" "$out/second.json" | head -20 >&2; fail "$id: a second grading differs"; }
echo "class test: a rerun resumes, and grading $id again gives the same results.json"

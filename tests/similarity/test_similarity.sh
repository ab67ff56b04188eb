#!/usr/bin/env bash
# The similarity report (label similarity): a synthetic class compared by grading/similarity (Dolos).
#   - Honest solutions of tasks 2 and 5 written from the handouts (class/ada, ben, cai, dee; each
#     earns full points from ./lab grade-submission), hal's task 1 alone, ivy's folder without a
#     task file, jan's and kim's unchanged stub of task 2.
#   - Planted in both tasks: eve hands in ben's task 2 and cai's task 5 verbatim (copied here),
#     fay cai's task 2 and ben's task 5 with every name of their own changed and their helpers and
#     functions reordered (class/fay), gus the reference with its names changed (sed below).
# In each of tasks 2 and 5 the three planted pairs must be the top three, at or above the report's
# threshold, and every other pair below it by a margin (MARGIN); the two unchanged stubs must
# count as nothing. The pages must exist and name the pairs, and bad input must get clear errors.
#   test_similarity.sh REPOSITORY_ROOT OUT
set -euo pipefail
root=$1 out=$2
here=$(cd "$(dirname "$0")" && pwd)
fail() { echo "similarity test: $*" >&2; exit 1; }
similarity() { node "$root/grading/similarity/similarity.mjs" "$@"; }
# The gap the threshold must leave on each side (grading/similarity/README.md: the honest pairs'
# maximum and the copies' minimum measured on this class are 0.19 and 0.14 from the threshold).
MARGIN=0.1

rm -rf "$out"
mkdir -p "$out"
cp -R "$here/class" "$out/class"
class=$out/class
mkdir "$class/eve" "$class/gus" "$class/jan" "$class/kim"
cp "$class/ben/task2_shapes.cpp" "$class/eve/"
cp "$class/cai/task5_materials.cpp" "$class/eve/"
cp "$root/student/task2_shapes.cpp" "$class/jan/"
cp "$root/student/task2_shapes.cpp" "$class/kim/"
# gus: the reference with every name of its own changed (functions, constants, variables).
sed -E 's/\bEDGE_SLACK\b/TOL/g; s/\bmiss\b/nothing/g; s/\bparallel\b/flat/g; s/\bhit_at\b/found/g;
	s/\bin_bounds\b/ok/g; s/\bret\b/res/g; s/\be1\b/ab/g; s/\be2\b/ac/g; s/\bs\b/w/g; s/\bn\b/m/g;
	s/\bdet\b/dd/g; s/\binv_det\b/id/g; s/\bu\b/p/g; s/\bv\b/r/g; s/\bt\b/x/g; s/([^.])\bnormal\b/\1nrm/g;
	s/\bo\b/org/g; s/\bd\b/dir2/g; s/\bl\b/dl/g; s/\bdisc\b/D/g; s/\bq\b/qq/g; s/\bt0\b/xa/g;
	s/\bt1\b/xb/g; s/\boutward\b/out/g' "$root/reference/task2_shapes.cpp" >"$class/gus/task2_shapes.cpp"
sed -E 's/\bout_dir\b/wo/g; s/\bdir\b/w/g; s/\bwas_internal\b/tir/g; s/\bcos_theta\b/mu/g;
	s/\boutside\b/above/g; s/\beta\b/ratio/g; s/\bsin2_out\b/so2/g; s/\bcos2_in\b/ci2/g;
	s/\bcos_in\b/ci/g; s/\bn_i\b/na/g; s/\bn_t\b/nb/g; s/\bcos_i\b/ca/g; s/\bsin2_t\b/sb2/g;
	s/\bcos_t\b/cb/g; s/\br_s\b/rs/g; s/\br_p\b/rp/g; s/\binternal\b/total/g; s/\brefracted\b/bent/g;
	s/\bF\b/R/g' "$root/reference/task5_materials.cpp" >"$class/gus/task5_materials.cpp"
for file in task2_shapes.cpp task5_materials.cpp; do
	changed=$(diff "$root/reference/$file" "$class/gus/$file" | grep -c '^>' || true)
	[ "$changed" -ge 15 ] || fail "gus's $file changes only $changed lines of the reference: the renaming did not apply"
done

start=$(date +%s%N)
similarity "$class" --out "$out/report" >"$out/similarity.log" 2>&1 || { cat "$out/similarity.log" >&2; fail "the report failed"; }
milliseconds=$((($(date +%s%N) - start) / 1000000))
csv=$out/report/similarity.csv
# The default threshold, as the report's last line says it: "... pairs at or above T: ...".
threshold=$(sed -nE 's/.* pairs at or above ([0-9.]+): .*/\1/p' "$out/similarity.log")
[ -n "$threshold" ] || fail "the report did not say its threshold: $(cat "$out/similarity.log")"

# pair_key TASK A B: the pair's CSV key, its names in alphabetical order.
csv_pairs() { awk -F, 'NR > 1 { a = $2; b = $3; if (b < a) { t = a; a = b; b = t } print $1 "," a "," b "," $5 "," $6 }' "$csv"; }
planted() {
	case "$1" in
	2,ben,eve | 2,cai,fay | 2,gus,reference | 5,cai,eve | 5,ben,fay | 5,gus,reference) return 0 ;;
	*) return 1 ;;
	esac
}
for task in 2 5; do
	top3=$(csv_pairs | awk -F, -v t="$task" '$1 == t && ++n <= 3')
	while IFS=, read -r n a b sim flagged; do
		planted "$n,$a,$b" || fail "task $task: the top three pairs should be the planted copies, but $a and $b ($sim) is among them"
		[ "$flagged" = 1 ] || fail "task $task: the planted pair $a and $b ($sim) is not flagged"
	done <<<"$top3"
	lowest_copy=$(echo "$top3" | cut -d, -f4 | sort -g | head -1)
	highest_other=$(csv_pairs | awk -F, -v t="$task" '$1 == t && ++n == 4 { print $4 }')
	awk -v copy="$lowest_copy" -v other="$highest_other" -v th="$threshold" -v m="$MARGIN" \
		'BEGIN { exit !(copy >= th + m && other <= th - m) }' ||
		fail "task $task: the copies' lowest similarity $lowest_copy and the other pairs' highest $highest_other" \
			"are not $MARGIN or more on either side of the threshold $threshold"
	others=$(csv_pairs | awk -F, -v t="$task" '$1 == t' | tail -n +4 | awk -F, '$5 == 1' | wc -l)
	[ "$others" = 0 ] || fail "task $task: $others pairs besides the planted ones are flagged"
	echo "similarity test: task $task: copies $(echo "$top3" | cut -d, -f2-4 | tr '\n' ' ')| most similar other pair $highest_other | threshold $threshold"
done
stubs=$(csv_pairs | awk -F, '$1 == 2 && $2 == "jan" && $3 == "kim" { print $4 }')
awk -v s="$stubs" -v th="$threshold" -v m="$MARGIN" 'BEGIN { exit !(s != "" && s <= th - m) }' ||
	fail "two unchanged stubs of task 2 (jan, kim) are ${stubs:-not compared} similar: the stub's code must count for no pair"
task1=$(csv_pairs | awk -F, '$1 == 1' | cut -d, -f2,3)
[ "$task1" = "hal,reference" ] || fail "task 1 (hal's file alone) should have one pair, hal and the reference, not: $task1"
[ "$(csv_pairs | awk -F, '$1 == 3' | wc -l)" = 0 ] || fail "task 3 has pairs, but no submission has its file"
echo "similarity test: two unchanged stubs $stubs similar; report written in $milliseconds ms"

# The pages: the summary names each planted pair and links its side-by-side page, which shows both.
report=$out/report
for page in index.html task2.html task5.html; do [ -s "$report/$page" ] || fail "no $page"; done
for pair in "2 ben eve" "2 cai fay" "2 gus reference" "5 cai eve" "5 ben fay" "5 gus reference"; do
	read -r task a b <<<"$pair"
	row=$(grep -E "<td>task $task</td>.*<td>$a</td>.*<td>($b|<em>the reference solution</em>)</td>|<td>task $task</td>.*<td>$b</td>.*<td>$a</td>" \
		"$report/index.html") || fail "index.html does not list task $task's pair $a and $b among the marked pairs"
	link=$(sed -E 's/.*href="([^"]+)".*/\1/' <<<"$row")
	[ -s "$report/$link" ] || fail "index.html links $link for $a and $b, which does not exist"
	grep -q ">$a<" "$report/$link" || fail "$link does not show $a's file"
	grep -q 'class="line longest"' "$report/$link" || fail "$link marks no longest fragment"
done
grep -q "ivy" "$report/index.html" || fail "index.html does not list ivy, whose folder holds no task file"
grep -q "ivy.*holds no task file" "$out/similarity.log" || fail "the report did not say that ivy holds no task file"

# Bad input: each a clear error and no report.
expect_error() { # STATUS MESSAGE ARGUMENTS...
	local status=$1 message=$2 got=0
	shift 2
	similarity "$@" >"$out/error.log" 2>&1 || got=$?
	[ "$got" = "$status" ] || fail "similarity $* exited with $got, not $status: $(cat "$out/error.log")"
	grep -qF -- "$message" "$out/error.log" || fail "similarity $* said '$(cat "$out/error.log")', not '$message'"
}
expect_error 2 "$out/none: no such folder" "$out/none" --out "$out/r1"
mkdir -p "$out/nothing/amy"
echo "notes" >"$out/nothing/amy/notes.txt"
expect_error 2 "no submission in $out/nothing holds a task file" "$out/nothing" --out "$out/r2"
mkdir -p "$out/broken/bob" "$out/broken/cat/task5_materials.cpp"
cp "$class/ada/task2_shapes.cpp" "$out/broken/bob/"
ln -s "$out/missing.cpp" "$out/broken/bob/task5_materials.cpp"
expect_error 1 "cannot read $out/broken/bob/task5_materials.cpp: it is a link to a file that does not exist" "$out/broken" --out "$out/r3"
expect_error 1 "cannot read $out/broken/cat/task5_materials.cpp: it is a folder, not a file" "$out/broken" --out "$out/r3"
if [ "$(id -u)" != 0 ]; then # root reads any file
	rm "$out/broken/bob/task5_materials.cpp"
	cp "$class/ada/task5_materials.cpp" "$out/broken/bob/"
	chmod 000 "$out/broken/bob/task5_materials.cpp"
	expect_error 1 "cannot read $out/broken/bob/task5_materials.cpp: permission denied" "$out/broken" --out "$out/r3"
fi
for dir in r1 r2 r3; do [ ! -e "$out/$dir" ] || fail "a failed report made $out/$dir"; done
expect_error 2 "holds files but no earlier similarity report" "$class" --out "$class/ada"
expect_error 2 "--threshold takes a number in (0, 1]" "$class" --out "$out/r4" --threshold 2
echo "similarity test: bad input gets clear errors"

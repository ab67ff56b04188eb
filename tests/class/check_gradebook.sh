#!/usr/bin/env bash
# Compares a gradebook with what the synthetic class must score (make_class.sh):
#   check_gradebook.sh RUBRIC EXPECTED.csv GRADEBOOK.csv MINIMUM
# Every submission graded, each task's points full (the rubric's), zero, or less than full as
# expected, and the total their sum; the class has at least MINIMUM submissions. Prints the first
# difference and exits 1, or prints a summary.
set -euo pipefail
rubric=$1 expected=$2 book=$3 minimum=$4
fail() { echo "gradebook check: $*" >&2; exit 1; }
# The rubric's points per task, in task order.
mapfile -t points < <(grep -o '"points": *[0-9.]*' "$rubric" | grep -o '[0-9.]*$')
[ ${#points[@]} -eq 8 ] || fail "$rubric does not give points for eight tasks"
rows=0
while IFS=, read -r id e1 e2 e3 e4 e5 e6 e7 e8; do
	[ "$id" = id ] && continue
	rows=$((rows + 1))
	line=$(grep "^$id," "$book") || fail "$id is missing from $book"
	IFS=, read -r _ p1 p2 p3 p4 p5 p6 p7 p8 total status <<<"$line"
	[ "$status" = graded ] || fail "$id: status '$status'"
	expect=("$e1" "$e2" "$e3" "$e4" "$e5" "$e6" "$e7" "$e8")
	got=("$p1" "$p2" "$p3" "$p4" "$p5" "$p6" "$p7" "$p8")
	sum=0
	for i in 0 1 2 3 4 5 6 7; do
		full=${points[$i]} p=${got[$i]}
		case "${expect[$i]}" in
		full) awk -v p="$p" -v f="$full" 'BEGIN { exit !(p == f) }' || fail "$id: task $((i + 1)) scored $p, expected all $full points" ;;
		zero) awk -v p="$p" 'BEGIN { exit !(p == 0) }' || fail "$id: task $((i + 1)) scored $p, expected 0" ;;
		less) awk -v p="$p" -v f="$full" 'BEGIN { exit !(p >= 0 && p < f) }' || fail "$id: task $((i + 1)) scored $p, expected fewer than $full" ;;
		esac
		sum=$(awk -v s="$sum" -v p="$p" 'BEGIN { printf "%.2f", s + p }')
	done
	awk -v s="$sum" -v t="$total" 'BEGIN { exit !((s - t) < 0.015 && (t - s) < 0.015) }' || fail "$id: total $total, but the tasks add up to $sum"
done <"$expected"
[ "$rows" -ge "$minimum" ] || fail "only $rows submissions expected: this synthetic class must have at least $minimum"
[ "$(($(wc -l <"$book") - 1))" -eq "$rows" ] || fail "$book has $(($(wc -l <"$book") - 1)) rows, expected $rows"
echo "gradebook check: all $rows submissions scored as expected"

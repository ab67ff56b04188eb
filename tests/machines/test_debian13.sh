#!/usr/bin/env bash
# A new student's loop on Debian 13 (trixie: Catch2 3, GCC 14, CMake 3.31), from a clean clone
# (labels acceptance and machines). A fresh Debian 13 root made by debootstrap, a student with sudo
# (tests/machines/debian_root.sh), `git clone` of this repository's HEAD, and as the student:
#   ./lab render                 installs the packages it names, builds, writes the PNG
#   ./lab grade N                every task (and 6-nee) on the stubs: fails, and its first line is the
#                                first failed test case ("FAIL  ..."), its message next; with the
#                                reference's file in student/: passes
#   ./lab grade-submission       the reference as a submission: full points, graded in bubblewrap
#   ./lab view                   answers its page
# The compiler warns about nothing, as GCC 12 does not. Then, entered as a
# container (chroot: bubblewrap cannot start), `./lab grade` still grades the student's own code with
# process limits and says so, and grade-submission refuses to run unsandboxed unless told.
#   test_debian13.sh REPOSITORY_ROOT OUT
set -euo pipefail
root=$(realpath "$1") out=$2
here=$(dirname "$(realpath "$0")")
# shellcheck source=debian_root.sh
source "$here/debian_root.sh"
fail() { echo "Debian 13 test: $*" >&2; exit 1; }
[ "$(id -u)" -eq 0 ] || fail "needs root (debootstrap, and entering the root)"
command -v debootstrap >/dev/null || fail "debootstrap is not installed (Debian package debootstrap)"
command -v curl >/dev/null || fail "curl is not installed"
mkdir -p "$out"
system=$out/debian13
home=$system/home/student
took() { echo "Debian 13 test: $1 in $((SECONDS - $2)) s"; }

start=$SECONDS
make_root trixie "$system" "$out/debootstrap.log" || fail "debootstrap trixie failed"
add_student "$system"
git clone -q "$root" "$home/lab"
chown -R 1000:1000 "$home/lab"
took "a Debian 13 root and a clone of $(git -C "$root" rev-parse --short HEAD)" "$start"

start=$SECONDS
student machine "$system" "./lab render" >"$out/render.out" 2>"$out/render.log" ||
	fail "./lab render failed: $(tail -20 "$out/render.log")"
png=$(sed -n 's/^wrote \([^ ]*\.png\)$/\1/p;T;q' "$out/render.out")
[ -n "$png" ] && [ -s "$home/lab/$png" ] || fail "./lab render did not write its PNG: $(tail -5 "$out/render.out")"
versions=$(in_root machine "$system" dpkg-query -W -f '${Package} ${Version}, ' libcatch2-dev g++ cmake libglm-dev \
	libcpp-httplib-dev libtinyobjloader-dev bubblewrap)
took "./lab render (packages: ${versions%, })" "$start"

# grade NAME EXPECTED N [FILE]: ./lab grade N as the student, with FILE of reference/ in student/.
grade() {
	local name=$1 expected=$2 n=$3 file=${4:-} status=0
	local script="./lab grade $n"
	[ -z "$file" ] || script="cp reference/$file student/ && $script; status=\$?; git checkout -q student/; exit \$status"
	student machine "$system" "$script" >"$out/$name.out" 2>"$out/$name.log" || status=$?
	if [ "$expected" = pass ]; then
		[ "$status" -eq 0 ] || fail "./lab grade $n failed the reference's $file: $(tail -20 "$out/$name.out")"
		grep -q "^All [0-9]* test cases pass.$" "$out/$name.out" || fail "./lab grade $n passed without saying so"
	else
		[ "$status" -ne 0 ] || fail "./lab grade $n passed the stub"
		head -1 "$out/$name.out" | grep -q '^FAIL  ' ||
			fail "./lab grade $n on the stub does not start with its first failed test case: $(head -3 "$out/$name.out")"
		sed -n 2p "$out/$name.out" | grep -q '^      [^ ]' ||
			fail "./lab grade $n on the stub: the second line is not the message: $(head -3 "$out/$name.out")"
		! grep -qE 'FAILED:|with expansion:|\.cpp:[0-9]+' "$out/$name.out" ||
			fail "./lab grade $n shows Catch2's file:line or expansions: $(grep -m3 -E 'FAILED:|with expansion:|\.cpp:[0-9]+' "$out/$name.out")"
	fi
	grep -q '^sandbox: bubblewrap' "$out/$name.out" || fail "./lab grade $n did not run in bubblewrap: $(grep '^sandbox:' "$out/$name.out")"
}
start=$SECONDS
for n in 1 2 3 4 5 6 7 8 6-nee; do
	file=$(cd "$root/reference" && ls task"${n%%-*}"_*.cpp)
	grade "grade_${n}_stub" fail "$n"
	grade "grade_${n}_reference" pass "$n" "$file"
done
took "./lab grade of every task, stub (fails) and reference (passes)" "$start"

start=$SECONDS
student machine "$system" "./lab grade-submission reference --out ~/graded" >"$out/grade_submission.log" 2>&1 ||
	fail "./lab grade-submission failed: $(tail -20 "$out/grade_submission.log")"
total=$(grep -o '"points": *[0-9.]*' "$root/grading/rubric.json" | grep -o '[0-9.]*$' | paste -sd+ | bc)
score=$(grep -m1 -o '^\s*"score": *[0-9.]*' "$home/graded/results.json" | grep -o '[0-9.]*$')
awk -v s="$score" -v t="$total" 'BEGIN { exit !(s == t) }' || fail "grade-submission of the reference scored $score of $total"
grep -q '"sandbox": "sandbox: bubblewrap' "$home/graded/task1.json" || fail "grade-submission did not grade in bubblewrap"
took "./lab grade-submission of the reference: $score of $total points" "$start"

start=$SECONDS
port=18024
page=$(view_page machine "$system" "$port" "$out/view.log")
grep -qi '<html' <<<"$page" || fail "./lab view did not answer its page: $(tail -20 "$out/view.log")"
took "./lab view answered its page" "$start"

# The compiler's warnings, in the lab's files or at its link-time optimization (GCC 12 has none).
warnings=$(cat "$out"/*.log | grep -E '^[^ ]+:[0-9]+:[0-9]+: warning:|^lto-wrapper: warning:' | sort -u || true)
[ -z "$warnings" ] || fail "GCC 14 warns:
$warnings"
echo "Debian 13 test: no warning of $(in_root machine "$system" g++ --version | head -1) in what the loop built"

# A container: bubblewrap cannot start. A student's grade still runs, with process limits, saying so;
# grading a submission refuses unless told.
start=$SECONDS
student container "$system" "./lab grade 1" >"$out/container_grade.out" 2>"$out/container_grade.log" &&
	fail "./lab grade 1 passed the stub in the container"
grep -q '^sandbox: PROCESS LIMITS ONLY (bubblewrap cannot run here' "$out/container_grade.out" ||
	fail "./lab grade 1 in the container does not say that it ran with process limits: $(tail -3 "$out/container_grade.out")"
head -1 "$out/container_grade.out" | grep -q '^FAIL  ' || fail "./lab grade 1 in the container did not grade"
status=0
student container "$system" "./lab grade-submission reference --out ~/graded-container --tasks 1" \
	>"$out/container_submission.log" 2>&1 || status=$?
[ "$status" -ne 0 ] || fail "grade-submission ran unsandboxed in the container without --allow-unsandboxed"
grep -qi 'allow-unsandboxed' "$out/container_submission.log" ||
	fail "grade-submission's refusal does not say how to go on: $(tail -5 "$out/container_submission.log")"
took "in a container: ./lab grade with process limits, saying so; grade-submission refused" "$start"

#!/usr/bin/env bash
# The class on GNU parallel (label parallel): the per-submission command as parallel's unit of work,
# on this machine as the only "host" (--sshlogin 2/: runs two jobs locally, the way a list of ssh
# hosts would run them remotely); its gradebook must equal grade-class's (test_class.sh).
#   test_parallel.sh REPOSITORY_ROOT KIT OUT
set -euo pipefail
root=$1 kit=$2 out=$3
fail() { echo "GNU parallel test: $*" >&2; exit 1; }
command -v parallel >/dev/null || fail "GNU parallel is not installed (Debian package parallel)"
[ -f "$out/gradebook.csv" ] || fail "no gradebook from grade-class in $out (run the class test first)"
dest=$out/parallel
rm -rf "$dest"
mkdir -p "$dest/submissions" "$dest/logs"
start=$SECONDS
# The lab's own command, as on a cluster whose hosts share the repository and its build folder.
export LAB_BUILD_DIR=${kit%/grading/kit.env}
parallel --will-cite --sshlogin 2/: --env LAB_BUILD_DIR \
	"$root/lab grade-submission {} --out $dest/submissions/{/} >$dest/logs/{/}.log 2>&1 || echo failed >$dest/logs/{/}.error" \
	::: "$out/class/submissions"/*
"$root/grading/bin/gradebook" "$dest" >/dev/null
echo "GNU parallel test: graded in $((SECONDS - start)) s"
cmp -s "$out/gradebook.csv" "$dest/gradebook.csv" ||
	{ diff "$out/gradebook.csv" "$dest/gradebook.csv" | head >&2; fail "the gradebook differs from grade-class's"; }
echo "GNU parallel test: the gradebook equals grade-class's"

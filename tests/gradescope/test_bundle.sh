#!/usr/bin/env bash
# The Gradescope autograder bundle's contents (label gradescope): ./lab autograder makes OUT/autograder.zip
# with a grading seed and leave to grade unsandboxed (a chroot, as test_autograder.sh uses, cannot
# make namespaces), and it must hold setup.sh and run_autograder at its root, the rubric, the seed
# it was given (readable by its owner alone) and that leave, the prebuilt reference and no reference
# source; and a run_autograder that cannot grade (here: setup.sh never ran) must still leave
# Gradescope a results.json that says so.
# test_autograder.sh (label acceptance) runs this first, then grades with the bundle in a Debian root.
#   test_bundle.sh REPOSITORY_ROOT OUT
set -euo pipefail
root=$1 out=$2
fail() { echo "bundle test: $*" >&2; exit 1; }
for program in zip unzip; do
	command -v "$program" >/dev/null || fail "$program is not installed (Debian packages zip, unzip)"
done
rm -rf "$out"
mkdir -p "$out"

start=$SECONDS
LAB_EXPORT_BUILD_DIR=$out/objects "$root/grading/bin/make-autograder" "$out/autograder.zip" --seed 4242 --allow-unsandboxed >/dev/null ||
	fail "./lab autograder failed"
unzip -Z1 "$out/autograder.zip" >"$out/bundle.txt"
has() { grep -qx "$1" "$out/bundle.txt" || fail "the bundle has no $1"; }
has setup.sh
has run_autograder
has grading/bin/grade-submission
has grading/rubric.json
has grading/seed
has grading/allow-unsandboxed
has grading/bin/sandboxed
has grading/bin/grade-task
unzip -Z "$out/autograder.zip" grading/seed | grep -q '^-rw-------' || fail "grading/seed is readable by others than its owner"
for n in 1 2 3 4 5 6 7 8; do has "prebuilt/libtask${n}_reference.a"; done
solution_sources=$(grep -xF -f <(cut -d' ' -f2 "$out/objects/shipped_compiled.txt") "$out/bundle.txt" || true)
[ -z "$solution_sources" ] || fail "the bundle holds solution sources: $(head -3 <<<"$solution_sources")"
echo "bundle test: bundle made ($(du -h "$out/autograder.zip" | cut -f1)) in $((SECONDS - start)) s"

# Unpacked as Gradescope unpacks it (the tree under OUT/autograder stands for /autograder).
grader=$out/autograder
mkdir -p "$grader/source" "$grader/submission" "$grader/results"
unzip -q "$out/autograder.zip" -d "$grader/source"
[ -x "$grader/source/setup.sh" ] && [ -x "$grader/source/run_autograder" ] || fail "setup.sh or run_autograder is not executable"
cmp -s "$grader/source/grading/rubric.json" "$root/grading/rubric.json" || fail "the bundle's rubric is not grading/rubric.json"
[ "$(cat "$grader/source/grading/seed")" = 4242 ] || fail "the bundle's seed is '$(cat "$grader/source/grading/seed")', not 4242"
echo "bundle test: setup.sh and run_autograder at the root, the rubric, the seed and the prebuilt reference, no reference source"

cp "$grader/source/run_autograder" "$grader/run_autograder" # as Gradescope does
cp "$root/reference/task1_camera.cpp" "$grader/submission/"
"$grader/run_autograder" >"$out/run_autograder.log" 2>&1 || fail "run_autograder failed: $(tail -5 "$out/run_autograder.log")"
results=$grader/results/results.json
[ -f "$results" ] || fail "run_autograder left no results.json when it could not grade"
grep -q '"score": 0' "$results" && grep -q "could not grade this submission" "$results" ||
	fail "results.json does not say that the submission could not be graded: $(cat "$results")"
echo "bundle test: without the grading kit, run_autograder still writes results.json: score 0, 'could not grade'"

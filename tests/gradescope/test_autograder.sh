#!/usr/bin/env bash
# The Gradescope autograder bundle at work (labels gradescope and acceptance): made and checked by
# test_bundle.sh, then a fresh Debian 12 root made by debootstrap, laid out like Gradescope's
# (/autograder/source, submission, results), runs its setup.sh and then run_autograder for example
# submissions, and each results.json must hold the expected score (all reference: full marks; the
# stubs: 0; one realistic mistake: fewer) with one entry per test case of the rubric.
#   test_autograder.sh REPOSITORY_ROOT OUT MUTANTS
# MUTANTS: the mutants' sources, made at configure time (BUILD/mutants, tests/mutants/README.md).
set -euo pipefail
root=$1 out=$2 mutants=$3
fail() { echo "autograder test: $*" >&2; exit 1; }
for program in debootstrap zip unzip chroot; do
	command -v "$program" >/dev/null || fail "$program is not installed (Debian packages debootstrap, zip, unzip)"
done
[ "$(id -u)" -eq 0 ] || fail "needs root (debootstrap and chroot)"
system=$out/debian
unmount() {
	for mount in "$system/dev/pts" "$system/dev" "$system/proc" "$system/sys"; do
		if mountpoint -q "$mount"; then umount -l "$mount"; fi
	done
	return 0
}
unmount # an earlier run stopped before its trap: never delete through its mounts
rm -rf "$out"
mkdir -p "$out"
trap unmount EXIT

bash "$(dirname "$0")/test_bundle.sh" "$root" "$out/bundle" || fail "the bundle test failed"
bundle=$out/bundle/autograder.zip

start=$SECONDS
debootstrap --variant=minbase bookworm "$system" http://deb.debian.org/debian >"$out/debootstrap.log" 2>&1 ||
	{ tail -20 "$out/debootstrap.log" >&2; fail "debootstrap failed"; }
cp /etc/resolv.conf "$system/etc/resolv.conf"
mount -t proc proc "$system/proc"
mount -t sysfs sys "$system/sys"
mount --bind /dev "$system/dev"
mount --bind /dev/pts "$system/dev/pts"
mkdir -p "$system/autograder/source" "$system/autograder/submission" "$system/autograder/results"
unzip -q "$bundle" -d "$system/autograder/source"
cp "$system/autograder/source/run_autograder" "$system/autograder/run_autograder" # as Gradescope does
echo "autograder test: a Debian 12 root in $((SECONDS - start)) s"

start=$SECONDS
chroot "$system" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root bash /autograder/source/setup.sh \
	>"$out/setup.log" 2>&1 || { tail -30 "$out/setup.log" >&2; fail "setup.sh failed in the Debian root"; }
echo "autograder test: setup.sh ran in $((SECONDS - start)) s"

# grade NAME EXPECTATION FILES...: one submission through run_autograder; EXPECTATION is full, zero
# or less (than full marks).
total=$(grep -o '"points": *[0-9.]*' "$root/grading/rubric.json" | grep -o '[0-9.]*$' | paste -sd+ | bc)
cases=$(grep -c '"id":' "$root/grading/rubric.json")
grade() {
	local name=$1 expectation=$2
	shift 2
	rm -rf "$system/autograder/submission"/* "$system/autograder/results"/*
	for file in "$@"; do cp "$file" "$system/autograder/submission/"; done
	local start=$SECONDS
	chroot "$system" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root /autograder/run_autograder \
		>"$out/$name.log" 2>&1 || fail "$name: run_autograder failed: $(tail -5 "$out/$name.log")"
	local results=$system/autograder/results/results.json
	[ -f "$results" ] || fail "$name: no results.json"
	cp "$results" "$out/$name.results.json"
	local score tests
	score=$(grep -m1 -o '^\s*"score": *[0-9.]*' "$results" | grep -o '[0-9.]*$')
	tests=$(grep -c '"max_score"' "$results")
	[ "$tests" -eq "$cases" ] || fail "$name: results.json has $tests test entries, the rubric $cases"
	case "$expectation" in
	full) awk -v s="$score" -v t="$total" 'BEGIN { exit !(s == t) }' || fail "$name: score $score, expected $total" ;;
	zero) awk -v s="$score" 'BEGIN { exit !(s == 0) }' || fail "$name: score $score, expected 0" ;;
	less) awk -v s="$score" -v t="$total" 'BEGIN { exit !(s > 0 && s < t) }' || fail "$name: score $score, expected 0 < score < $total" ;;
	esac
	grep -q "inputs: drawn from the grading seed" "$results" || grep -q "grading seed" "$system/autograder/results/graded/task1.json" ||
		fail "$name: the bundle's grading seed was not used"
	echo "autograder test: $name scored $score of $total ($expectation) in $((SECONDS - start)) s; $(grep -o 'sandbox: [^(;]*' "$system/autograder/results/graded/task1.json" | head -1)"
}
grade reference full "$root"/reference/task*.cpp
grade stubs zero
mistake=$out/mistake
mkdir -p "$mistake"
cp "$root"/reference/task*.cpp "$mistake/"
cp "$mutants/task4/no_offset.cpp" "$mistake/task4_path.cpp"
grade one_mistake less "$mistake"/task*.cpp

# What a student holding the release can hand in (tests/security/test_reference_holder.cpp), filled
# in as the security suite fills it in: the compiled reference of task 3 as assembly, a task 1 that
# would become another program, a task 6 that names its own integrator as the framework's, a task 7
# that would be the reference if its compile could see an earlier task's build, a task 8 right only
# on its public cases (which the bundle's grading seed changes). Each earns nothing:
# 0 with the stubs of the other tasks.
hostile=$out/hostile
mkdir -p "$hostile"
fill() { # NAME: tests/security/hostile/NAME with its placeholders filled in
	sed -e "/@CORRECT_TASK1_IF@/{r $root/tests/security/hostile/correct_task1_if.inc" -e 'd}' \
		-e "/@REFERENCE_TASK7@/{r $root/reference/task7_env_light.cpp" -e 'd}' \
		-e "/@STUB_TASK6@/{r $root/student/task6_direct_lighting.cpp" -e 'd}' \
		-e "/@STUB_TASK7@/{r $root/student/task7_env_light.cpp" -e 'd}' \
		-e "s|@OUT@|/autograder/results/graded|g" "$root/tests/security/hostile/$1"
}
fill task1_if_exec_works.cpp >"$hostile/task1_camera.cpp"
fill task6_integrator_named_as_framework.cpp >"$hostile/task6_direct_lighting.cpp"
fill task7_if_earlier_builds_visible.cpp >"$hostile/task7_env_light.cpp"
fill task8_public_cases_only.cpp >"$hostile/task8_adaptive.cpp" # under the bundle's seed: the stub's part
# shellcheck source=/dev/null
source "$(dirname "$mutants")/grading/kit.env"
{
	printf '#define PASTE(a, b) a##b\n#define EMIT PASTE(__as, m__)\nEMIT(R"lab(\n'
	# shellcheck disable=SC2086
	"$LAB_CXX" $LAB_CXXFLAGS -S -o - "$root/reference/task3_bvh.cpp"
	printf '\n)lab");\n'
} >"$hostile/task3_bvh.cpp"
grade reference_holder zero "$hostile"/task*.cpp
# Task 8 is worth 0 points by default, so its score proves nothing: its closed-form test cases, drawn
# from the bundle's seed, must have failed.
python3 - "$system/autograder/results/graded/task8.json" <<'PYTHON' || fail "reference_holder: task 8's public-cases file passed a closed-form test case"
import json, sys
closed_forms = ("pixel_converged: a pixel stops once", "pixel_converged: never before min_samples",
                "sample_pixel: samples 0, 1, 2", "sample_pixel: checks after every batch")
cases = json.load(open(sys.argv[1]))["test_cases"]
passed = [c["name"] for c in cases if c["passed"] and c["name"].startswith(closed_forms)]
print("autograder test: task 8's public-cases file, closed forms passed under the seed:", passed)
sys.exit(1 if passed or len(cases) != 7 else 0)
PYTHON

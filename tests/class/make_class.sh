#!/usr/bin/env bash
# A synthetic class for the class-grading tests (labels class, parallel, slurm):
#   make_class.sh REPOSITORY_ROOT OUT small|full MUTANTS
# writes OUT/submissions/<id>/ and OUT/expected.csv, what each must score: per task "full" (the
# task's points), "zero", or "less" (a realistic mistake: fewer than full).
#   full   (./lab acceptance) 23 submissions: all reference, all stubs, files that are not task
#          files, each task alone, mixtures, realistic mistakes (the mutants' sources in MUTANTS, the
#          build's mutants/ folder, made at configure time from tests/mutants/) and hostile files
#          (tests/security/hostile/), the other tasks being the reference;
#   small  (./lab test) four of them whose gradebook rows all differ: every task scored full, zero
#          and less somewhere, a hostile file, files that are not task files; enough to prove that
#          a scheduler grades each submission and the gradebook comes back whole.
set -euo pipefail
root=$1
out=$2
size=$3
mutants=$4
[[ $size == small || $size == full ]] || { echo "make_class.sh: the class is small or full, not '$size'" >&2; exit 2; }
files=(task1_camera.cpp task2_shapes.cpp task3_bvh.cpp task4_path.cpp task5_materials.cpp
	task6_direct_lighting.cpp task7_env_light.cpp task8_adaptive.cpp)
rm -rf "$out"
mkdir -p "$out/submissions"
echo "id,task1,task2,task3,task4,task5,task6,task7,task8" >"$out/expected.csv"

# submission ID EXPECTATIONS(8, comma-separated; task 8 is worth 0 points in the default rubric) [TASK=FILE ...]: tasks given a FILE use it, tasks
# expected "zero" without one are left out (the stub), every other task is the reference.
submission() {
	local id=$1 expected=$2
	shift 2
	local dir=$out/submissions/$id
	mkdir -p "$dir"
	IFS=, read -r -a expect <<<"$expected"
	for n in 1 2 3 4 5 6 7 8; do
		[ "${expect[$((n - 1))]}" = zero ] || cp "$root/reference/${files[$((n - 1))]}" "$dir/"
	done
	for given in "$@"; do
		local n=${given%%=*} file=${given#*=}
		cp "$file" "$dir/${files[$((n - 1))]}"
	done
	echo "$id,$expected" >>"$out/expected.csv"
}

stubs_and_notes() { # the stubs, with files that are not task files
	submission stubs_and_notes zero,zero,zero,zero,zero,zero,zero,zero
	echo "my notes" >"$out/submissions/stubs_and_notes/notes.txt"
	mkdir -p "$out/submissions/stubs_and_notes/build"
	echo "not a task file" >"$out/submissions/stubs_and_notes/build/task1_camera.cpp"
}

mutant() { # mutant TASK NAME
	local expect=full,full,full,full,full,full,full,full
	expect=$(echo "$expect" | awk -F, -v n="$1" 'BEGIN { OFS = "," } { $n = "less"; print }')
	submission "mistake_task$1_$2" "$expect" "$1=$mutants/task$1/$2.cpp"
}

hostile() { # hostile TASK FILE
	local expect=full,full,full,full,full,full,full,full
	expect=$(echo "$expect" | awk -F, -v n="$1" 'BEGIN { OFS = "," } { $n = "zero"; print }')
	submission "hostile_$2" "$expect" "$1=$root/tests/security/hostile/$2.cpp"
}

if [ "$size" = small ]; then
	submission part_one full,full,full,zero,zero,zero,zero,zero
	mutant 4 no_offset
	hostile 7 task7_forged_records
	stubs_and_notes
	exit 0
fi

submission all_reference full,full,full,full,full,full,full,full
submission all_stubs zero,zero,zero,zero,zero,zero,zero,zero
stubs_and_notes
for n in 1 2 3 4 5 6 7; do
	expect=zero,zero,zero,zero,zero,zero,zero,zero
	expect=$(echo "$expect" | awk -F, -v n="$n" 'BEGIN { OFS = "," } { $n = "full"; print }')
	submission "only_task$n" "$expect"
done
submission part_one full,full,full,zero,zero,zero,zero,zero
submission part_two zero,zero,zero,full,full,full,full,full
submission odd_tasks full,zero,full,zero,full,zero,full,zero

mutant 1 upside_down
mutant 1 no_jitter
mutant 4 no_offset
mutant 5 eta_inverted
mutant 6 mixture_without_halves
mutant 7 pdf_without_sin_theta

hostile 1 task1_exit_in_static_initializer
hostile 1 task1_fork_survivor
hostile 3 task3_include_reference
hostile 7 task7_forged_records

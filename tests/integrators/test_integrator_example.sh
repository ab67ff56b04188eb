#!/usr/bin/env bash
# Adding an integrator is one file (README.md, "Adding an integrator"; label acceptance): in a
# scratch copy of the tree, the README's example, direct lighting alone, is added as
# framework/render/integrators/direct_integrator.cpp and nothing else changes. The reference
# renderer built there must list it in --help, and its render of the Cornell box must estimate the
# image next-event estimation renders at --max-depth 1 (MEAN_DIFFERENCE: a z-test of the means).
# Builds the scratch tree's reference renderer (a few minutes).
#   test_integrator_example.sh REPOSITORY_ROOT OUT MEAN_DIFFERENCE
set -euo pipefail
root=$1 out=$2 mean_difference=$3
fail() { echo "integrator example test: $*" >&2; exit 1; }
rm -rf "$out"
mkdir -p "$out"
scratch=$out/tree
mkdir "$scratch"
tar -C "$root" --exclude=./.git --exclude='./build*' --exclude=./out --exclude=./report --exclude=node_modules -cf - . |
	tar -C "$scratch" -xf -

# The example, from between the README's markers (without the code fence).
example=$scratch/framework/render/integrators/direct_integrator.cpp
sed -n '/^<!-- integrator example: begin/,/^<!-- integrator example: end -->$/p' "$root/README.md" |
	sed '1,2d;$d' | sed '$d' >"$example"
grep -q 'Integrator_Row row{"direct"' "$example" || fail "README.md has no integrator example between its markers"

start=$SECONDS
cmake -S "$scratch" -B "$out/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DLAB_LTO=OFF >"$out/configure.log" 2>&1 ||
	fail "the scratch tree does not configure: $(tail -20 "$out/configure.log")"
cmake --build "$out/build" --target pathtracer_reference >"$out/build.log" 2>&1 ||
	fail "the scratch tree's renderer does not build: $(grep -m5 -A5 'error' "$out/build.log")"
! grep -q 'warning:' "$out/build.log" || fail "the example builds with warnings: $(grep -m5 'warning:' "$out/build.log")"
renderer=$out/build/tasks/pathtracer_reference
echo "integrator example test: the scratch tree's renderer built in $((SECONDS - start)) s"

"$renderer" --help | grep -q '^  direct  *direct lighting alone' || fail "--help does not list the integrator direct"
render() {
	local integrator=$1
	"$renderer" "$scratch/scenes/cornell_box.json" --integrator "$integrator" --max-depth 1 --spp 64 --width 64 \
		--height 64 --sampler independent --seed 11 --quiet --out "$out/$integrator.png" --exr "$out/$integrator.exr" \
		--variance "$out/${integrator}_var.exr" || fail "--integrator $integrator does not render"
}
render direct
render nee
"$mean_difference" "$out/direct.exr" "$out/direct_var.exr" "$out/nee.exr" "$out/nee_var.exr" 64 ||
	fail "--integrator direct does not estimate the image of --integrator nee --max-depth 1"
echo "integrator example test: one new file adds --integrator direct, which renders the image of direct light"

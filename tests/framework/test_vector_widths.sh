#!/usr/bin/env bash
# The fast accelerator's two vector widths answer alike (framework/api/accelerator.h; the
# instructors' wide_bvh_queries.h): renders whose queries take four lanes (LAB_VECTOR_WIDTH=4, the
# path of CPUs without AVX2) are the renders of eight lanes byte for byte, on scenes that use every
# query (a mesh's own tree and a scene's, closest and any hit, flat meshes and spheres). An unknown
# width is refused by name; on a CPU without AVX2, so is 8.
#
# usage: test_vector_widths.sh PATHTRACER_REFERENCE REPOSITORY_ROOT
set -euo pipefail
renderer=$1 root=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "vector widths test: $*" >&2; exit 1; }

render() { # WIDTH SCENE OUT.exr
	LAB_VECTOR_WIDTH=$1 "$renderer" "$root/scenes/$2.json" --spp 4 --width 96 --height 72 --threads 2 --quiet \
		--out "$tmp/image.png" --exr "$3"
}

if grep -qw avx2 /proc/cpuinfo 2>/dev/null && [ "$(uname -m)" = x86_64 ]; then
	for scene in cornell_spheres bunny_sun many_lights; do
		render 4 "$scene" "$tmp/$scene-4.exr" || fail "$scene with four lanes failed"
		render 8 "$scene" "$tmp/$scene-8.exr" || fail "$scene with eight lanes failed"
		cmp -s "$tmp/$scene-4.exr" "$tmp/$scene-8.exr" ||
			fail "$scene: four lanes and eight render different images; the two node tests must answer alike (four_wide_tests.h and eight_wide_queries.cpp of the instructors' repository)"
		echo "vector widths test: $scene, four and eight lanes, the same image"
	done
else
	render 4 cornell_spheres "$tmp/four.exr" || fail "four lanes failed"
	if render 8 cornell_spheres "$tmp/eight.exr" 2>"$tmp/error.txt"; then
		fail "LAB_VECTOR_WIDTH=8 rendered on a CPU without AVX2"
	fi
	grep -q "LAB_VECTOR_WIDTH=8: this CPU has no AVX2" "$tmp/error.txt" || fail "width 8 refused without naming why: $(cat "$tmp/error.txt")"
	echo "vector widths test: no AVX2 here: four lanes render, eight are refused by name"
fi

if render 6 cornell_spheres "$tmp/six.exr" 2>"$tmp/error.txt"; then fail "LAB_VECTOR_WIDTH=6 was accepted"; fi
grep -q "LAB_VECTOR_WIDTH=6: expected 4 or 8" "$tmp/error.txt" || fail "width 6 refused without naming it: $(cat "$tmp/error.txt")"
echo "vector widths test: LAB_VECTOR_WIDTH=6 refused by name"

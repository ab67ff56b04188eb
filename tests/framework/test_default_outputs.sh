#!/usr/bin/env bash
# The two renderers as built (label framework): without --out, pathtracer_reference writes
# out/<scene>.png and pathtracer_student out/<scene>_student.png, so that `./lab render` and
# `./lab render-student` never replace each other's picture.
#
# usage: test_default_outputs.sh PATHTRACER_REFERENCE PATHTRACER_STUDENT SCENE.json
set -euo pipefail

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "default outputs test: $*" >&2; exit 1; }
name=$(basename "$3" .json)

cd "$tmp"
for program in "$1" "$2"; do
	"$program" "$3" --spp 1 --width 8 --height 6 --max-depth 1 --quiet || fail "$program failed"
done
files=$(find . -type f | sort | tr '\n' ' ')
[ "$files" = "./out/$name.png ./out/${name}_student.png " ] ||
	fail "expected out/$name.png and out/${name}_student.png, found: $files"
echo "default outputs test: out/$name.png and out/${name}_student.png"

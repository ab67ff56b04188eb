#!/usr/bin/env bash
# Two task files may each define a helper of the same name and still link into one renderer
# (label framework): every stub (student/task*.cpp) opens an anonymous namespace for the student's
# helpers, and a helper written there stays private to its file.
#   (a) each stub has the anonymous namespace;
#   (b) the same helper, `int lab_helper()`, put into the anonymous namespace of all eight stubs:
#       the eight objects link together (ld -r reports a clash of global symbols);
#   (c) the check can fail: the helper put before the namespace, at global scope, in two stubs
#       does not link.
#
# usage: test_stub_helpers_link.sh REPOSITORY_ROOT CXX_COMPILER
set -euo pipefail

root=$1
cxx=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "stub helpers link test: $*" >&2; exit 1; }

# with_helper STUB OUT WHERE: a copy of STUB with the helper inserted `inside` its anonymous
# namespace (after the line `namespace {`) or `outside` it (before that line).
with_helper() {
	local stub=$1 out=$2 where=$3
	awk -v where="$where" '
		/^namespace \{/ && !done {
			if (where == "outside") print "int lab_helper() { return 1; }"
			print
			if (where == "inside") print "int lab_helper() { return 1; }"
			done = 1
			next
		}
		{ print }' "$stub" >"$out"
}

compile() {
	"$cxx" -std=c++17 -O0 -w -I "$root/framework/api" -c "$1" -o "$2" 2>"$2.log" ||
		{ cat "$2.log" >&2; fail "$(basename "$1") does not compile with a helper inserted"; }
}

objects=()
for stub in "$root"/student/task*.cpp; do
	name=$(basename "$stub" .cpp)
	grep -q '^namespace {' "$stub" ||
		fail "student/$name.cpp has no anonymous namespace (a line 'namespace {') for the student's helpers"
	with_helper "$stub" "$tmp/$name.cpp" inside
	compile "$tmp/$name.cpp" "$tmp/$name.o"
	objects+=("$tmp/$name.o")
done
[ ${#objects[@]} -eq 8 ] || fail "expected 8 stubs in student/ (tasks 1-7 and task 8), found ${#objects[@]}"
ld -r "${objects[@]}" -o "$tmp/all.o" 2>"$tmp/link.log" ||
	{ cat "$tmp/link.log" >&2; fail "the eight stubs with the same helper in their anonymous namespaces do not link together"; }
echo "stub helpers link test: the same helper in all eight stubs' anonymous namespaces links"

# The control: at global scope the same helper in two files is a clash, and ld -r says so.
for name in task1_camera task2_shapes; do
	with_helper "$root/student/$name.cpp" "$tmp/${name}_global.cpp" outside
	compile "$tmp/${name}_global.cpp" "$tmp/${name}_global.o"
done
if ld -r "$tmp/task1_camera_global.o" "$tmp/task2_shapes_global.o" -o "$tmp/clash.o" 2>"$tmp/clash.log"; then
	fail "two stubs with the same global helper linked: this test could not see a clash"
fi
grep -q "multiple definition of .lab_helper()" "$tmp/clash.log" ||
	{ cat "$tmp/clash.log" >&2; fail "the clash of a global helper was not reported as a multiple definition"; }
echo "stub helpers link test: the same helper at global scope in two stubs does not link, as expected"

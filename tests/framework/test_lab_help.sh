#!/usr/bin/env bash
# ./lab's help (label framework):
#   (a) `./lab help` lists the commands within 80 columns;
#   (b) for every command, `./lab help CMD`, `./lab CMD --help` and `./lab CMD -h` print the same
#       usage of that command alone ("usage: ./lab CMD ..."), within 80 columns, with status 0, and
#       build, install or test nothing (cmake, ctest, apt-get and dpkg-query are stand-ins that
#       record any call, and the build folder must not appear);
#   (c) usage errors exit with status 2: an unknown command, help for one, a bad task number;
#   (d) in a student release (a lab script with no reference folder beside it) the help lists no command
#       marked (instructors), and asking for one is a usage error.
#
# usage: test_lab_help.sh REPOSITORY_ROOT
set -euo pipefail

root=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "lab help test: $*" >&2; exit 1; }

mkdir "$tmp/bin"
for tool in cmake ctest apt-get dpkg-query sudo; do
	printf '#!/bin/sh\necho "%s $*" >>"%s/calls"\nexit 0\n' "$tool" "$tmp" >"$tmp/bin/$tool"
	chmod +x "$tmp/bin/$tool"
done
export PATH=$tmp/bin:$PATH
export LAB_BUILD_DIR=$tmp/build

# fits_80 NAME FILE: every line of FILE has at most 80 characters.
fits_80() {
	local long
	long=$(awk 'length > 80 { printf "line %d (%d characters): %s\n", NR, length, $0 }' "$2")
	[ -z "$long" ] || fail "$1 has lines longer than 80 columns:"$'\n'"$long"
}

nothing_ran() {
	[ ! -e "$tmp/calls" ] || fail "$1 ran $(head -1 "$tmp/calls") (help must build nothing)"
	[ ! -e "$LAB_BUILD_DIR" ] || fail "$1 made the build folder $LAB_BUILD_DIR"
}

"$root/lab" help >"$tmp/help.txt" || fail "./lab help exited with status $?"
fits_80 "./lab help" "$tmp/help.txt"
nothing_ran "./lab help"
mapfile -t commands < <(awk '/^  [a-z]/ { print $1 }' "$tmp/help.txt")
[ ${#commands[@]} -ge 10 ] || fail "./lab help lists only ${#commands[@]} commands: ${commands[*]}"

for command in "${commands[@]}"; do
	"$root/lab" help "$command" >"$tmp/$command.help" || fail "./lab help $command exited with status $?"
	head -1 "$tmp/$command.help" | grep -q "^usage: ./lab $command\b" ||
		fail "./lab help $command does not start with 'usage: ./lab $command': $(head -1 "$tmp/$command.help")"
	fits_80 "./lab help $command" "$tmp/$command.help"
	for flag in --help -h; do
		"$root/lab" "$command" "$flag" >"$tmp/$command$flag" || fail "./lab $command $flag exited with status $?"
		cmp -s "$tmp/$command.help" "$tmp/$command$flag" || fail "./lab $command $flag differs from ./lab help $command"
		nothing_ran "./lab $command $flag"
	done
done
echo "lab help test: ./lab help, and the usage of each of its ${#commands[@]} commands, fit 80 columns and build nothing"

# expect_usage_error ARGS...: ./lab ARGS exits with status 2.
expect_usage_error() {
	local status=0
	"$root/lab" "$@" >/dev/null 2>&1 || status=$?
	[ "$status" -eq 2 ] || fail "./lab $* exited with status $status, expected 2 (a usage error)"
	nothing_ran "./lab $*"
}
expect_usage_error no-such-command
expect_usage_error help no-such-command
expect_usage_error grade 9
expect_usage_error grade
echo "lab help test: usage errors exit with status 2"

# A student release's lab: no reference folder beside it.
mkdir "$tmp/release"
cp "$root/lab" "$tmp/release/lab"
"$tmp/release/lab" help >"$tmp/release_help.txt"
! grep -q "(instructors)" "$tmp/release_help.txt" ||
	fail "a student release's ./lab help lists instructors' commands: $(grep "(instructors)" "$tmp/release_help.txt" | head -3)"
grep -q "^  grade N" "$tmp/release_help.txt" || fail "a student release's ./lab help does not list grade"
status=0
"$tmp/release/lab" help export >/dev/null 2>&1 || status=$?
[ "$status" -eq 2 ] || fail "a student release's ./lab help export exited with status $status, expected 2"
echo "lab help test: a student release's ./lab help lists no instructors' command"

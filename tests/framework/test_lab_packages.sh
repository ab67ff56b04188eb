#!/usr/bin/env bash
# The lab script on a machine where the account has neither root nor sudo (label framework): with every
# package present it asks for nothing; with one missing, `./lab render` names it, prints the one
# command that installs it and exits non-zero, without running apt-get or sudo. Run as an ordinary
# user (uid 65534 when this runs as root). dpkg-query, sudo and apt-get are stand-ins on PATH that
# record each call: dpkg-query reports every package installed but those in LAB_TEST_MISSING;
# sudo is there but needs a password this account does not have, as on a lab machine.
#   test_lab_packages.sh REPOSITORY_ROOT
set -euo pipefail
root=$(realpath "$1")
fail() { echo "lab packages test: $*" >&2; exit 1; }

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
chmod 755 "$scratch"
mkdir "$scratch/bin" "$scratch/lab"
cp "$root/lab" "$scratch/lab/lab" # setup needs nothing else of the tree
cat >"$scratch/bin/dpkg-query" <<'EOF'
#!/bin/sh
for package; do :; done
echo "dpkg-query $package" >>"$LAB_TEST_CALLS"
case " $LAB_TEST_MISSING " in *" $package "*) echo "dpkg-query: no packages found matching $package" >&2; exit 1 ;; esac
printf 'install ok installed'
EOF
cat >"$scratch/bin/sudo" <<'EOF'
#!/bin/sh
echo "sudo $*" >>"$LAB_TEST_CALLS"
echo "sudo: a password is required" >&2
exit 1
EOF
cat >"$scratch/bin/apt-get" <<'EOF'
#!/bin/sh
echo "apt-get $*" >>"$LAB_TEST_CALLS"
echo "E: Could not open lock file /var/lib/dpkg/lock-frontend - open (13: Permission denied)" >&2
exit 100
EOF
chmod 755 "$scratch"/bin/*
calls=$scratch/calls
touch "$calls"
chmod 666 "$calls"

as_user=()
[ "$(id -u)" -ne 0 ] || as_user=(setpriv --reuid=65534 --regid=65534 --clear-groups --inh-caps=-all)
# run_lab MISSING COMMAND...: the lab script as the ordinary user, with no terminal; its output in
# $scratch/out.
run_lab() {
	local missing=$1
	shift
	: >"$calls"
	"${as_user[@]}" env -i PATH="$scratch/bin:/usr/bin:/bin" HOME="$scratch" LAB_BUILD_DIR="$scratch/build" \
		LAB_TEST_CALLS="$calls" LAB_TEST_MISSING="$missing" "$scratch/lab/lab" "$@" </dev/null >"$scratch/out" 2>&1
}

# Every package present: nothing is installed and nobody is asked.
run_lab "" setup || fail "./lab setup failed with every package present: $(cat "$scratch/out")"
grep -q '^dpkg-query ' "$calls" || fail "./lab setup did not check the packages"
! grep -qE '^(sudo|apt-get) ' "$calls" || fail "./lab setup asked for root with every package present: $(grep -E '^(sudo|apt-get)' "$calls")"

# One missing, no root, no sudo: the message and the command, status non-zero, no apt-get at all.
status=0
run_lab "libglm-dev" render || status=$?
[ "$status" -ne 0 ] || fail "./lab render exited 0 with libglm-dev missing: $(cat "$scratch/out")"
grep -qF "these Debian packages are missing: libglm-dev" "$scratch/out" ||
	fail "./lab render does not name the missing package: $(cat "$scratch/out")"
grep -qxF "  sudo apt-get install --no-install-recommends libglm-dev" "$scratch/out" ||
	fail "./lab render does not print the command that installs it: $(cat "$scratch/out")"
! grep -qE '^(E|W): |Permission denied' "$scratch/out" || fail "./lab render shows apt's own error: $(cat "$scratch/out")"
! grep -q '^apt-get ' "$calls" || fail "./lab ran apt-get without root: $(grep '^apt-get' "$calls")"
[ ! -e "$scratch/build/CMakeCache.txt" ] || fail "./lab configured the build although a package is missing"
echo "lab packages test: as uid $("${as_user[@]}" id -u), every package present: no sudo, no apt-get; libglm-dev missing:"
sed 's/^/  /' "$scratch/out"
echo "  (exit status $status)"

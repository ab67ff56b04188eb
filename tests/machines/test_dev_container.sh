#!/usr/bin/env bash
# The dev container (.devcontainer/, labels acceptance and machines), without Docker, which this
# machine does not run: its Dockerfile is Debian 12 and one step, .devcontainer/setup.sh; this runs
# that same script in a fresh Debian 12 root made by debootstrap and entered as a container
# (tests/machines/debian_root.sh: chroot, where bubblewrap cannot start, as in most Docker
# containers). Then, as the container's user in a clone of this repository: `./lab setup` finds
# every package and asks for nothing; `./lab grade 1` grades the stub with process limits and says
# so in its last lines; `./lab view` answers its page.
# Not run here: Docker's build of the image itself, VS Code's or Codespaces' port forwarding.
#   test_dev_container.sh REPOSITORY_ROOT OUT
set -euo pipefail
root=$(realpath "$1") out=$2
here=$(dirname "$(realpath "$0")")
# shellcheck source=debian_root.sh
source "$here/debian_root.sh"
fail() { echo "dev container test: $*" >&2; exit 1; }
[ "$(id -u)" -eq 0 ] || fail "needs root (debootstrap, and entering the root)"
command -v curl >/dev/null || fail "curl is not installed"
devcontainer=$root/.devcontainer
took() { echo "dev container test: $1 in $((SECONDS - $2)) s"; }

# What the files say: the Dockerfile is Debian 12 and runs setup.sh; the container's user and port.
grep -qx 'FROM debian:12' "$devcontainer/Dockerfile" || fail "the Dockerfile does not start from debian:12"
grep -q '^RUN bash /tmp/lab-setup/setup.sh /tmp/lab-setup/lab' "$devcontainer/Dockerfile" ||
	fail "the Dockerfile does not run .devcontainer/setup.sh"
[ "$(grep -c '^RUN' "$devcontainer/Dockerfile")" -eq 1 ] || fail "the Dockerfile has steps this test does not run"
grep -q '"remoteUser": "student"' "$devcontainer/devcontainer.json" || fail "devcontainer.json's user is not student"
grep -q '"forwardPorts": \[8024\]' "$devcontainer/devcontainer.json" || fail "devcontainer.json does not forward 8024"

mkdir -p "$out"
system=$out/debian12
start=$SECONDS
rm -rf "$system"
mkdir -p "$system"
debootstrap --variant=minbase bookworm "$system" http://deb.debian.org/debian >"$out/debootstrap.log" 2>&1 ||
	fail "debootstrap bookworm failed: $(tail -5 "$out/debootstrap.log")"
# The Dockerfile's COPY and RUN.
mkdir -p "$system/tmp/lab-setup"
cp "$root/lab" "$devcontainer/setup.sh" "$system/tmp/lab-setup/"
in_root container "$system" bash /tmp/lab-setup/setup.sh /tmp/lab-setup/lab >"$out/setup.log" 2>&1 ||
	fail "setup.sh failed: $(tail -20 "$out/setup.log")"
rm -rf "$system/tmp/lab-setup"
took "a Debian 12 root set up by .devcontainer/setup.sh" "$start"

git clone -q "$root" "$system/home/student/lab"
chown -R 1000:1000 "$system/home/student/lab"
student container "$system" "./lab setup" >"$out/lab_setup.log" 2>&1 || fail "./lab setup failed: $(cat "$out/lab_setup.log")"
! grep -q 'installing' "$out/lab_setup.log" || fail "the container lacks packages: $(cat "$out/lab_setup.log")"

start=$SECONDS
student container "$system" "./lab grade 1" >"$out/grade.out" 2>"$out/grade.log" && fail "./lab grade 1 passed the stub"
head -1 "$out/grade.out" | grep -q '^FAIL  ' || fail "./lab grade 1 did not grade: $(tail -20 "$out/grade.log")"
grep -q '^sandbox: PROCESS LIMITS ONLY (bubblewrap cannot run here' "$out/grade.out" ||
	fail "./lab grade 1 does not say that your code ran with process limits: $(tail -3 "$out/grade.out")"
took "./lab grade 1 (process limits, said so)" "$start"

start=$SECONDS
port=18025
page=$(view_page container "$system" "$port" "$out/view.log")
grep -qi '<html' <<<"$page" || fail "./lab view did not answer its page: $(tail -20 "$out/view.log")"
took "./lab view answered its page on port $port" "$start"

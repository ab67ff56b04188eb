#!/usr/bin/env bash
# The dev container's setup (Dockerfile), run as root in a fresh Debian 12: git, the lab's own
# package setup (`./lab setup`: everything the lab builds, grades and views with), and the user
# "student" (uid 1000, sudo without a password, as VS Code's dev containers have), whom
# devcontainer.json works as. The lab's acceptance runs (machine_dev_container) run this same script
# in a Debian 12 root made by debootstrap.
#   setup.sh LAB_SCRIPT
set -euo pipefail
lab=$1
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends git ca-certificates sudo >/dev/null
LAB_BUILD_DIR=$(mktemp -d) "$lab" setup
useradd --create-home --uid 1000 --shell /bin/bash student
echo "student ALL=(ALL) NOPASSWD: ALL" >/etc/sudoers.d/student
chmod 440 /etc/sudoers.d/student
rm -rf /var/lib/apt/lists/*

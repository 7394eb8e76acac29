#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The armhf cross build's target root (docs/INSTALL.md, "armhf"): robuterd's and the tests' -dev
# packages for armhf, extracted (not installed: no maintainer script runs, no binfmt needed) by
# mmdebstrap into ROOT, once. Debian's cross g++ compiles against it with --sysroot and qemu-arm
# runs the tests with -L ROOT. Not multiarch: this machine's mirror has served an inconsistent
# armhf security index, which made armhf -dev packages uninstallable beside the host's; bookworm's
# main suite alone is consistent.
# Usage: tools/deps/armhf-sysroot.sh ROOT
set -euo pipefail
root="${1:?usage: armhf-sysroot.sh ROOT}"
[[ -f "$root/.robuter-sysroot" ]] && exit 0
mirror="${ROBUTER_VM_MIRROR:-http://deb.debian.org/debian}"
rm -rf "$root.part"
mkdir -p "$(dirname "$root")"
mmdebstrap --variant=extract --architectures=armhf \
  --include=libc6-dev,libstdc++-12-dev,libgtest-dev,libgmock-dev,libfmt-dev,libtomlplusplus-dev,libeigen3-dev,libcli11-dev,libcairo2-dev,libfontconfig-dev,libreadline-dev,libsystemd-dev \
  bookworm "$root.part" "deb $mirror bookworm main"
# qemu-arm -L ROOT opens a path under ROOT first: the root's own /dev (device nodes mmdebstrap
# made) would shadow the host's, and /dev/ptmx there answers ENODEV (the pty tests fail).
rm -rf "$root.part/dev"
rm -rf "$root" && mv "$root.part" "$root"
touch "$root/.robuter-sysroot"
echo "armhf-sysroot: $root"

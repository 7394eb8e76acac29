#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Prepares a Debian cross build for TRIPLET: the target architecture in dpkg, toolchain, qemu-user, target libraries.
# Usage: tools/deps/cross.sh TRIPLET   (aarch64-linux-gnu or arm-linux-gnueabihf)
set -euo pipefail
triplet=${1:?usage: cross.sh TRIPLET}
here=$(cd "$(dirname "$0")" && pwd)
case "$triplet" in
  aarch64-linux-gnu) arch=arm64 ;;
  arm-linux-gnueabihf) arch=armhf ;;
  *) echo "cross: unknown triplet '$triplet' (aarch64-linux-gnu or arm-linux-gnueabihf)" >&2; exit 2 ;;
esac

# The target architecture must be known to dpkg before its packages can be installed.
# armhf: not multiarch (the mirror's armhf security index has been inconsistent): the cross
# compiler, qemu-user and mmdebstrap from the host's architecture, and an extracted armhf root as
# the sysroot (cmake/toolchains/arm-linux-gnueabihf-sysroot.cmake, tools/deps/armhf-sysroot.sh).
if [[ "$arch" == armhf ]]; then
  list=$(mktemp)
  trap 'rm -f "$list"' EXIT
  printf '%s\n' g++-arm-linux-gnueabihf qemu-user-static mmdebstrap pkg-config cmake ninja-build > "$list"
  "$here/ensure.sh" "$list"
  exec "$here/armhf-sysroot.sh" "${ROBUTER_ARMHF_SYSROOT:-${XDG_CACHE_HOME:-$HOME/.cache}/robuterd-armhf-root}"
fi

if ! dpkg --print-foreign-architectures | grep -qx "$arch"; then
  if [[ $(id -u) -ne 0 ]]; then
    echo "cross: run as root:  dpkg --add-architecture $arch && apt-get update" >&2
    exit 1
  fi
  echo "cross: adding the $arch architecture to dpkg"
  dpkg --add-architecture "$arch"
  apt-get update -qq || echo "cross: apt-get update reported errors; going on with the indexes there are" >&2
fi

list=$(mktemp)
trap 'rm -f "$list"' EXIT
sed -e "s/@TRIPLET@/$triplet/g" -e "s/@ARCH@/$arch/g" "$here/cross-packages.txt" > "$list"
"$here/ensure.sh" "$list"


#!/usr/bin/env bash
# Prepares a Debian cross build for TRIPLET: target architecture, toolchain, qemu-user, target libraries; unpacks libserial-dev into ROOT.
# Usage: tools/deps/cross.sh TRIPLET ROOT   (TRIPLET: aarch64-linux-gnu or arm-linux-gnueabihf)
set -euo pipefail
triplet=${1:?usage: cross.sh TRIPLET ROOT}
root=${2:?usage: cross.sh TRIPLET ROOT}
here=$(cd "$(dirname "$0")" && pwd)
case "$triplet" in
  aarch64-linux-gnu) arch=arm64 ;;
  arm-linux-gnueabihf) arch=armhf ;;
  *) echo "cross: unknown triplet '$triplet' (aarch64-linux-gnu or arm-linux-gnueabihf)" >&2; exit 2 ;;
esac

# The target architecture must be known to dpkg before its packages can be installed.
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

# libserial-dev:$arch would replace the host's libserial-dev, so it is unpacked into ROOT:
# its headers, a libserial.so pointing at the installed run-time library, and a .pc naming both.
if [[ ! -f "$root/pkgconfig/libserial.pc" ]]; then
  echo "cross: unpacking libserial-dev:$arch into $root"
  rm -rf "$root/unpack" && mkdir -p "$root/unpack" "$root/pkgconfig" "$root/lib"
  (cd "$root/unpack" && apt-get download -q "libserial-dev:$arch" >/dev/null && dpkg-deb -x ./libserial-dev_*.deb .)
  so=$(ls /usr/lib/"$triplet"/libserial.so.1 2>/dev/null || true)
  [[ -n "$so" ]] || { echo "cross: /usr/lib/$triplet/libserial.so.1 missing (libserial1:$arch)" >&2; exit 1; }
  ln -sf "$so" "$root/lib/libserial.so"
  sed -e "s|^prefix=.*|prefix=$root/unpack/usr|" -e "s|^libdir=.*|libdir=$root/lib|" \
    "$root/unpack/usr/lib/$triplet/pkgconfig/libserial.pc" > "$root/pkgconfig/libserial.pc"
fi

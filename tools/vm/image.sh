#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds (once, cached outside the tree) the Debian 12 guest of `make test-vm`: a root with systemd,
# a Debian kernel, can-utils, iproute2 and robuterd's run-time libraries, as an ext4 disk image,
# with the kernel and initrd beside it. Prints the cache folder on its last line.
# Usage: tools/vm/image.sh [CACHE_ROOT [ARCH]]   (default ${XDG_CACHE_HOME:-$HOME/.cache}/robuterd-vm, amd64)
# ARCH arm64 needs qemu-user-static's binfmt handler on the host (the root's maintainer scripts
# run under it); the script mounts binfmt_misc when it is not (root only).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
cache_root="${1:-${XDG_CACHE_HOME:-$HOME/.cache}/robuterd-vm}"
arch="${2:-amd64}"
mirror="${ROBUTER_VM_MIRROR:-http://deb.debian.org/debian}"
case "$arch" in
  amd64) kernel=linux-image-amd64 ;;
  arm64) kernel=linux-image-arm64 ;;
  *) echo "image: ARCH must be amd64 or arm64" >&2; exit 2 ;;
esac
# What the guest holds. robuterd's libraries (its .deb's Depends, names only: the guest has no
# network, so dpkg -i must find them there), python3-serial for the checks, can-utils for candump.
packages=(systemd systemd-sysv udev kmod "$kernel" iproute2 can-utils procps
          python3-minimal python3-serial
          libcairo2 libfmt9 libtomlplusplus3 libreadline8 libsystemd0 libstdc++6 fonts-dejavu-core)
# The key: what goes into the root (packages, mirror, the hooks below, the guest's unit).
hooks_start=$(grep -n '^# HOOKS' "$here/image.sh" | head -1 | cut -d: -f1)
key="$( { printf '%s\n' "$arch" "${packages[@]}" "$mirror"; sed -n "${hooks_start},\$p" "$here/image.sh";
          cat "$here/guest/robuter-vm-run.service"; } | sha256sum | cut -c1-16)"
dir="$cache_root/$arch-$key"
if [[ -f "$dir/ready" ]]; then
  echo "image: cached" >&2
  echo "$dir"
  exit 0
fi
for tool in mmdebstrap mkfs.ext4; do
  command -v "$tool" >/dev/null || { echo "image: $tool missing (apt-get install mmdebstrap e2fsprogs)" >&2; exit 2; }
done
if [[ "$arch" != "$(dpkg --print-architecture)" ]]; then
  binfmt=/proc/sys/fs/binfmt_misc
  [[ -f $binfmt/register ]] || mount -t binfmt_misc binfmt_misc $binfmt 2>/dev/null || true
  [[ -f $binfmt/qemu-aarch64 ]] || update-binfmts --enable qemu-aarch64 2>/dev/null || true
  [[ -f $binfmt/qemu-aarch64 ]] || { echo "image: no binfmt handler for arm64 (apt-get install qemu-user-static binfmt-support; binfmt_misc mounted)" >&2; exit 2; }
fi
rm -rf "$dir" && mkdir -p "$dir"
root="$dir/root"
t0=$(date +%s.%N)
include="$(IFS=,; echo "${packages[*]}")"
# HOOKS (from here on, the text is part of the cache key)
# The guest's own settings, made inside the root by mmdebstrap's hooks: a root password-less
# console, the payload disk's runner started at boot, no getty on the serial line (the runner
# writes there), vcan loaded at boot.
mmdebstrap --variant=minbase --architectures="$arch" --include="$include" \
  --customize-hook='echo robuter-vm > "$1/etc/hostname"' \
  --customize-hook='echo "/dev/vda / ext4 rw,errors=remount-ro 0 1" > "$1/etc/fstab"' \
  --customize-hook='chroot "$1" passwd -d root' \
  --customize-hook='chroot "$1" systemctl mask serial-getty@ttyS0.service serial-getty@ttyAMA0.service getty@tty1.service systemd-timesyncd.service apt-daily.timer apt-daily-upgrade.timer 2>/dev/null || true' \
  --customize-hook="copy-in $here/guest/robuter-vm-run.service /etc/systemd/system" \
  --customize-hook='chroot "$1" systemctl enable robuter-vm-run.service' \
  --customize-hook='echo vcan > "$1/etc/modules-load.d/vcan.conf"' \
  bookworm "$root" "deb $mirror bookworm main" "deb ${mirror%/debian}/debian-security bookworm-security main" >&2
echo "$arch" > "$dir/arch"
cp "$(ls "$root"/boot/vmlinuz-* | sort -V | tail -1)" "$dir/vmlinuz"
cp "$(ls "$root"/boot/initrd.img-* | sort -V | tail -1)" "$dir/initrd.img"
size_mb=$(( $(du -sm "$root" | cut -f1) + 600 ))
mkfs.ext4 -q -F -L robuter-root -d "$root" "$dir/root.img" "${size_mb}M" >&2
rm -rf "$root"
t1=$(date +%s.%N)
awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.1f\n", b - a }' > "$dir/build-seconds"
touch "$dir/ready"
echo "image: built in $(cat "$dir/build-seconds") s" >&2
echo "$dir"

#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# make test-vm: the package on real Linux. Boots the cached Debian 12 guest (tools/vm/image.sh) under
# QEMU with the .deb on a second disk; the guest installs it, brings vcan0 up, runs the simulated
# CAN nodes and checks robuterd under systemd (tools/vm/guest/guest-checks.py). Prints every
# check, the figures, and a last line "N passed, N failed".
# Usage: tools/vm/run.sh DEB   (the guest's architecture is the package's: amd64 or arm64;
#        ROBUTER_VM_ACCEL=auto|tcg|kvm, ROBUTER_VM_CACHE=DIR, ROBUTER_VM_TIMEOUT=s, ROBUTER_VM_VERBOSE=1)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
deb="$(realpath "$1")"
arch="$(dpkg-deb -f "$deb" Architecture)"
accel="${ROBUTER_VM_ACCEL:-auto}"
case "$arch" in
  amd64) qemu=(qemu-system-x86_64) console=ttyS0 ;;
  arm64) qemu=(qemu-system-aarch64 -M virt) console=ttyAMA0
         [[ "$arch" == "$(dpkg --print-architecture)" ]] || accel=tcg ;;  # a foreign guest: emulated
  *) echo "test-vm: a package for amd64 or arm64, not '$arch'"; echo "0 passed, 1 failed"; exit 1 ;;
esac
timeout_s="${ROBUTER_VM_TIMEOUT:-$([[ $accel == tcg && $arch != "$(dpkg --print-architecture)" ]] && echo 2400 || echo 900)}"
work="$(mktemp -d /tmp/robuter-vm.XXXXXX)"
trap 'rm -rf "$work"' EXIT

fail() { echo "test-vm: $*"; echo "0 passed, 1 failed"; exit 1; }
now() { date +%s.%N; }
since() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.1f", b - a }'; }

t=$(now)
img="$("$here/image.sh" "${ROBUTER_VM_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/robuterd-vm}" "$arch" | tail -1)" ||
  fail "the $arch image was not built"
echo "figure image (build, or the cache's check): $(since "$t") s$( [[ -f "$img/build-seconds" ]] && echo "; first build took $(cat "$img/build-seconds") s")"

# The payload disk: the package and the guest's scripts.
mkdir "$work/payload"
cp "$deb" "$here/guest/guest-run.sh" "$here/guest/guest-checks.py" "$work/payload/"
mkfs.ext4 -q -F -L payload -d "$work/payload" "$work/payload.img" $(( $(du -sm "$work/payload" | cut -f1) + 16 ))M >/dev/null
qemu-img create -q -f qcow2 -F raw -b "$img/root.img" "$work/root.qcow2"   # the cached image stays as it is

# KVM only where it is shown to boot (nested virtualisation can hang at the BIOS): a probe boots
# the kernel for a few seconds and looks for its banner on the console.
# The probe's verdict is kept beside the image (delete it to probe again).
probe_file="$img/accel-probe"
if [[ "$accel" == auto && -f "$probe_file" ]]; then
  accel="$(cat "$probe_file")"
  echo "test-vm: accelerator $accel (probed before: $probe_file)"
elif [[ "$accel" == auto ]]; then
  accel=tcg
  if [[ -r /dev/kvm && -w /dev/kvm ]]; then
    timeout 20 "${qemu[@]}" -accel kvm -cpu host -m 512 -display none -monitor none -no-reboot \
      -serial "file:$work/probe.log" -kernel "$img/vmlinuz" -append "console=$console panic=-1 root=/dev/null" \
      >/dev/null 2>&1 || true
    grep -q "Linux version" "$work/probe.log" 2>/dev/null && accel=kvm
  fi
  echo "$accel" > "$probe_file"
  echo "test-vm: accelerator $accel (KVM probe: $( [[ $accel == kvm ]] && echo "the kernel booted" || echo "no kernel banner in 20 s, or no /dev/kvm"))"
fi
case "$accel" in
  kvm) cpu=(-accel kvm -cpu host) ;;
  tcg) cpu=(-accel tcg -cpu max) ;;
  *) fail "ROBUTER_VM_ACCEL must be auto, tcg or kvm" ;;
esac

t=$(now)
echo "test-vm: $arch guest, $accel"
timeout "$timeout_s" "${qemu[@]}" "${cpu[@]}" -m 1024 -smp 2 -display none -monitor none -no-reboot \
  -serial stdio -kernel "$img/vmlinuz" -initrd "$img/initrd.img" \
  -append "root=/dev/vda rw console=$console quiet loglevel=3 systemd.show_status=0 panic=-1" \
  -drive "file=$work/root.qcow2,if=virtio,format=qcow2" -drive "file=$work/payload.img,if=virtio,format=raw,readonly=on" \
  -nic none </dev/null | while IFS= read -r line; do
    line="${line%$'\r'}"
    case "$line" in
      "vm: up:"*) echo "figure boot (QEMU start to the guest's payload service): $(since "$t") s"; echo "$line" ;;
      vm:*|ok*|FAIL*|figure*|"+ "*|*" passed, "*" failed") echo "$line" ;;
      *) [[ -n "${ROBUTER_VM_VERBOSE:-}" ]] && echo "  | $line" ;;
    esac
    true
  done | tee "$work/out.log" || true  # a timeout or a crash: the summary check below says so
echo "figure whole VM run (boot, checks, power-off): $(since "$t") s"
summary="$(grep -E '^[0-9]+ passed, [0-9]+ failed$' "$work/out.log" | tail -1)" ||
  fail "the guest never reported (timeout ${timeout_s} s or a crash; ROBUTER_VM_VERBOSE=1 shows its console)"
echo "$summary"
[[ "$summary" == *" 0 failed" ]]

#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# robuter-doors-run's worlds: a name found in --worlds-dir; a name found in an installed
# prefix's share/robuterd/worlds beside its bin/ (the tool copied into a temporary prefix,
# with a world that exists only there); an unknown world refused with exit status 2.
set -u
tool=$1; worlds=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
status=0
ok() { echo "ok   $1"; }
fail() { echo "FAIL $1"; status=1; }

out=$("$tool" --worlds-dir "$worlds" --world door90 --seed 1 2>&1); rc=$?
if [[ $rc -eq 0 && $out == *"doors crossed"* ]]; then ok "--worlds-dir, --world door90: $out"
else fail "--worlds-dir, --world door90: exit $rc: $out"; fi

mkdir -p "$tmp/prefix/bin" "$tmp/prefix/share/robuterd/worlds"
cp "$tool" "$tmp/prefix/bin/robuter-doors-run"
cp "$worlds/door90.toml" "$tmp/prefix/share/robuterd/worlds/only_here.toml"
help=$("$tmp/prefix/bin/robuter-doors-run" --help 2>&1)
if [[ $help == *"$tmp/prefix/share/robuterd/worlds"* ]]; then ok "installed: --help names the prefix's worlds folder"
else fail "installed: --help does not name $tmp/prefix/share/robuterd/worlds: $help"; fi
out=$("$tmp/prefix/bin/robuter-doors-run" --world only_here --seed 1 2>&1); rc=$?
if [[ $rc -eq 0 && $out == *"doors crossed"* ]]; then ok "installed: --world only_here: $out"
else fail "installed: --world only_here: exit $rc: $out"; fi

out=$("$tool" --worlds-dir "$worlds" --world nosuch 2>&1); rc=$?
if [[ $rc -eq 2 && $out == *"no world 'nosuch'"* ]]; then ok "unknown world: $out"
else fail "unknown world: exit $rc, expected 2: $out"; fi
exit $status

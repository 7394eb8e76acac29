#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs every benchmark section (tools/bench/NN-*.sh) in order; each prints its own figures.
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
export ROBUTER_BUILD=${ROBUTER_BUILD:-build}
export ROBUTER_BIN=${ROBUTER_BIN:-$ROBUTER_BUILD/bin}
status=0
for section in "$here"/[0-9]*.sh; do
  [[ -e "$section" ]] || continue
  echo "=== $(basename "$section" .sh) ==="
  bash "$section" || { echo "bench section $(basename "$section") failed"; status=1; }
  echo
done
exit $status

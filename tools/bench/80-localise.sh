#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Localisation (docs/LOCALISATION.md): on the simulated lab, the filter's error beside odometry's on
# the same tours, kidnapping and global-start recovery, each step's CPU time; then the building
# floor's corridors. ROBUTER_BENCH_LOCALISE_SEEDS=n (lab), ROBUTER_BENCH_LOCALISE_LAPS=n (floor).
set -euo pipefail
bin=${ROBUTER_BIN:-build/bin}
if [[ ! -x "$bin/robuter_localise_bench" ]]; then
  echo "80-localise: $bin/robuter_localise_bench not built (make bench builds it)" >&2
  exit 1
fi
"$bin/robuter_localise_bench" "${ROBUTER_BENCH_LOCALISE_SEEDS:-10}" "${ROBUTER_BENCH_LOCALISE_LAPS:-3}"

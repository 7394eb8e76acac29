#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Localisation on the simulated lab (docs/LOCALISATION.md): the filter's error beside odometry's on
# the same tours, kidnapping and global-start recovery, each step's CPU time. ROBUTER_BENCH_LOCALISE_SEEDS=n.
set -euo pipefail
bin=${ROBUTER_BIN:-build/bin}
if [[ ! -x "$bin/robuter_localise_bench" ]]; then
  echo "80-localise: $bin/robuter_localise_bench not built (make bench builds it)" >&2
  exit 1
fi
"$bin/robuter_localise_bench" "${ROBUTER_BENCH_LOCALISE_SEEDS:-10}"

#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Simulator figures: simulated seconds per wall second of the pure world model (default world,
# robot stepped every 10 ms, all 24 ring sonars every 40 ms, the pan-tilt pair every 30 ms).
set -euo pipefail
bin=${ROBUTER_BIN:-build/bin}
here=$(cd "$(dirname "$0")/../.." && pwd)
world=${ROBUTER_BENCH_SIM_WORLD:-$here/worlds/default.toml}
if [[ ! -x "$bin/robuter_sim_bench" ]]; then
  echo "robuter_sim_bench not built (configure with -DROBUTER_BENCH=ON)"
  exit 1
fi
"$bin/robuter_sim_bench" "$world"
echo "target: far above 200 simulated s per wall s"

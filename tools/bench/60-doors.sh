#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Door crossing: 100 seeded starts per door width (lateral ±40 cm, heading ±20°, 1.5 m in front),
# AG then Ad on the whole simulated firmware with the emulated pan-tilt; success rate, mean
# crossing time, every failure with its reason. Target: ≥ 95 % at 90 cm, every failure stopped.
# ROBUTER_BENCH_DOORS_STARTS changes the count; ROBUTER_BENCH_DOORS_SONAR=realistic runs the
# realistic sonar model (docs/SIMULATOR.md) with odometry noise, =stress (or the older
# ROBUTER_BENCH_DOORS_NOISE=1) the stress model with odometry noise; by default the ideal one.
set -euo pipefail
bin=${ROBUTER_BIN:-build/bin}
starts=${ROBUTER_BENCH_DOORS_STARTS:-100}
sonar=${ROBUTER_BENCH_DOORS_SONAR:-$([[ ${ROBUTER_BENCH_DOORS_NOISE:-0} == 1 ]] && echo stress || echo ideal)}
case "$sonar" in
  ideal) noise=clean ;;
  stress) noise=noise ;;
  realistic) noise=realistic ;;
  *) echo "60-doors: ROBUTER_BENCH_DOORS_SONAR=$sonar: expected ideal, stress or realistic" >&2; exit 2 ;;
esac
if [[ ! -x "$bin/robuter_doors_bench" ]]; then
  echo "60-doors: $bin/robuter_doors_bench not built (cmake --build <dir> --target robuter_doors_bench)" >&2
  exit 1
fi
exec "$bin/robuter_doors_bench" "$starts" "$noise"

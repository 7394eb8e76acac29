#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Door crossing: 100 seeded starts per door width (lateral ±40 cm, heading ±20°, 1.5 m in front),
# AG then Ad on the whole simulated firmware with the emulated pan-tilt; success rate, mean
# crossing time, every failure with its reason. Target: ≥ 95 % at 90 cm, every failure stopped.
# ROBUTER_BENCH_DOORS_STARTS changes the count; ROBUTER_BENCH_DOORS_NOISE=1 adds sonar and
# odometry noise.
set -euo pipefail
bin=${ROBUTER_BIN:-build/bin}
starts=${ROBUTER_BENCH_DOORS_STARTS:-100}
noise=$([[ ${ROBUTER_BENCH_DOORS_NOISE:-0} == 1 ]] && echo noise || echo clean)
if [[ ! -x "$bin/robuter_doors_bench" ]]; then
  echo "60-doors: $bin/robuter_doors_bench not built (cmake --build <dir> --target robuter_doors_bench)" >&2
  exit 1
fi
exec "$bin/robuter_doors_bench" "$starts" "$noise"

#!/usr/bin/env bash
# Safety figures, before/after the watch schedule: range read to zero speed, ring latency, stopped full-scan time.
set -euo pipefail
bin=${ROBUTER_BIN:-build/bin}
trials=${ROBUTER_BENCH_SAFETY_TRIALS:-200}
if [[ ! -x "$bin/robuter_safety_bench" ]]; then
  echo "50-safety: $bin/robuter_safety_bench not built (configure with -DROBUTER_BENCH=ON)" >&2
  exit 1
fi
exec "$bin/robuter_safety_bench" "$trials"

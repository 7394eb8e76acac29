#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Safety figures: range read to zero speed at the drive (seeded trials), ring latency and stopped
# full-scan time before/after the watch schedule, then the random-sequence property of
# docs/SAFETY.md §12–§13 at bench size (10,000 sequences; make test runs 2,000).
set -euo pipefail
bin=${ROBUTER_BIN:-build/bin}
trials=${ROBUTER_BENCH_SAFETY_TRIALS:-200}
sequences=${ROBUTER_BENCH_SAFETY_SEQUENCES:-10000}
if [[ ! -x "$bin/robuter_safety_bench" ]]; then
  echo "50-safety: $bin/robuter_safety_bench not built (configure with -DROBUTER_BENCH=ON)" >&2
  exit 1
fi
"$bin/robuter_safety_bench" "$trials"
if [[ ! -x "$bin/safety_sim_test" ]]; then
  echo "50-safety: $bin/safety_sim_test not built" >&2
  exit 1
fi
echo "50-safety: random sequences, envelope rule, $sequences sequences"
ROBUTER_SAFETY_SIM_SEQUENCES=$sequences exec "$bin/safety_sim_test" --gtest_filter='*RandomSequences*'

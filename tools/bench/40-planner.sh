#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Planner bench: the firmware's planner (PASS/FAIL per target), MovingAI per family (every map and
# scenario, each engine vs BGL astar_search), 1000x1000 full plans, replans. ROBUTER_BENCH_STRIDE=n
# runs every n-th scenario, ROBUTER_BENCH_REPS the repetitions per engine (default 3).
set -euo pipefail
bin=${ROBUTER_BIN:-build/bin}
root=$(cd "$(dirname "$0")/../.." && pwd)
data=${ROBUTER_MOVINGAI_DIR:-$root/../shared/data/movingai}
if [[ ! -x "$bin/robuter-plan-bench" ]]; then
  echo "40-planner: $bin/robuter-plan-bench not built (configure with -DROBUTER_BENCH=ON)" >&2
  exit 1
fi
# The rectangle's footprint against an exact polygon-overlap test, on 10^5 random poses over the
# full turn (make test runs 10^4; tests/planner/test_fullturn.cpp).
if [[ -x "$bin/planner_tests" ]]; then
  ROBUTER_FOOTPRINT_POSES=100000 "$bin/planner_tests" --gtest_filter='FullTurnFootprint.NeverFree*' |
    grep -E 'poses:|OK|FAILED'
fi
# One sync's parts after a 10 x 10 block (begin_sync, the 32 class and 32 bit layers), min of 30.
if [[ -x "$bin/robuter-layer-sync-bench" ]]; then "$bin/robuter-layer-sync-bench"; fi
# The planner module's own worst activation (thread CPU, all its parts together: readings, sync,
# field, search or tree step, path following) in the seed 000 lab runs (tests/planner_sim: no
# prior map, and the default window), five times each: the figure the firmware's budget meets.
if [[ -x "$bin/planner_sim_test" ]]; then
  worsts=$(for _ in 1 2 3 4 5; do "$bin/planner_sim_test" --gtest_filter='*Seed000*'; done |
    sed -nE 's/.*worst activation ([0-9]+) us.*/\1/p' | sort -n)
  if [[ -n "$worsts" ]]; then
    n=$(wc -l <<<"$worsts")
    med=$(sed -n "$(( (n + 1) / 2 ))p" <<<"$worsts")
    max=$(tail -1 <<<"$worsts")
    verdict=$([[ $med -lt 5000 ]] && echo PASS || echo FAIL)
    echo "planner module, seed 000 lab runs: worst activation per run, median $(awk -v v="$med" 'BEGIN{printf "%.2f", v/1000}') ms" \
      "(of $n; all: $(awk '{printf "%s%.2f", (NR>1 ? " " : ""), $1/1000}' <<<"$worsts") ms; largest $(awk -v v="$max" 'BEGIN{printf "%.2f", v/1000}') ms)" \
      "  target < 5 ms on the median (a VM's stolen time shows as a single run's outlier): $verdict"
  fi
fi
"$bin/robuter-plan-bench" "$data" "$root"

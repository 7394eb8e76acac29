#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Planner bench: optimal search vs BGL astar_search on MovingAI maps, 1000x1000 full plans, replans.
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
exec "$bin/robuter-plan-bench" "$data"

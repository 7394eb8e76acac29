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
exec "$bin/robuter-plan-bench" "$data"

#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Whole-firmware simulation speed: robuterd --sim --speed max on the default world, every module
# running, all 24 ring sonars firing and the pan-tilt sweeping with its two sonars (--ptu-sweep):
# simulated seconds per wall second (and per CPU second), from --stats and the shell's timer.
set -euo pipefail
bin=${ROBUTER_BIN:-build/bin}
here=$(cd "$(dirname "$0")/../.." && pwd)
world=${ROBUTER_BENCH_SIM_WORLD:-$here/worlds/default.toml}
ticks=${ROBUTER_BENCH_SIM_TICKS:-3600000}  # ten simulated hours at the default 10 ms tick
if [[ ! -x "$bin/robuterd" ]]; then
  echo "robuterd not built ($bin/robuterd)"
  exit 1
fi
out=$(mktemp); times=$(mktemp); trap 'rm -f "$out" "$times"' EXIT

# measure N: runs N ticks; sets wall, cpu (s) and sim (simulated s, from the --stats tick line).
measure() {
  local TIMEFORMAT='%R %U %S'
  { time "$bin/robuterd" --sim --sonar-model ideal --world "$world" --speed max --ticks "$1" --ptu-sweep --stats \
      --log-level warn >"$out" 2>&1; } 2>"$times"
  read -r wall user sys <"$times"
  cpu=$(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.3f", u + s }')
  # "tick 10000 µs: 360000 ticks, lateness ..."
  sim=$(awk '/^tick / { gsub(":", "", $3); print $2 * $4 / 1e6; exit }' "$out")
  [[ -n "$sim" ]] || { echo "robuterd printed no statistics:"; cat "$out"; exit 1; }
}

measure 100            # start-up and shut-down alone (world, tables, log thread)
base_wall=$wall; base_cpu=$cpu
measure "$ticks"
awk -v sim="$sim" -v wall="$wall" -v cpu="$cpu" -v bw="$base_wall" -v bc="$base_cpu" -v n="$ticks" 'BEGIN {
  printf "robuterd --sim --speed max --ptu-sweep, default world, %d ticks = %.0f simulated s\n", n, sim
  printf "  whole run: %.2f s wall, %.2f s CPU -> %.0f simulated s per wall s, %.0f per CPU s\n", wall, cpu, sim / wall, sim / cpu
  printf "  start-up and shut-down alone (100 ticks): %.2f s wall, %.2f s CPU\n", bw, bc
  if (wall - bw > 0.05)
    printf "  steady state: %.0f simulated s per wall s, %.2f us wall per 10 ms tick\n", sim / (wall - bw), 1e6 * (wall - bw) / n
}'
echo "target: >= 200 simulated s per wall s"

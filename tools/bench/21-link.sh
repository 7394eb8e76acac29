#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Link figures: pty round-trip latency of BO over 10,000 requests with the 10 ms tick running,
# as a normal process and with SCHED_FIFO (robuterd realtime = true, the client under chrt),
# against the floor measured in the same run: a bare pty that answers each line at once.
set -euo pipefail
bin=${ROBUTER_BIN:-build/bin}
n=${ROBUTER_BENCH_LINK_REQUESTS:-10000}
dir=$(mktemp -d)
trap 'pkill -INT -f "$dir/robuter.pty" 2>/dev/null; rm -rf "$dir"' EXIT

# run_case LABEL CONFIG CLIENT_PREFIX...
run_case() {
  local label=$1 cfg=$2; shift 2
  local pty="$dir/robuter.pty"
  "$bin/robuterd" --sim --sonar-model ideal --pty "$pty" --log-level warn ${cfg:+--config "$cfg"} >"$dir/log" 2>&1 &
  local pid=$!
  for _ in $(seq 100); do [[ -L "$pty" ]] && break; sleep 0.05; done
  echo -n "$label: "
  local out
  out=$("$@" "$bin/robuterctl" --port "$pty" --bench "$n" --bench-line BO)
  echo "$out"
  local a b
  a=$(p50 "$out"); b=$(p50 "$floor")
  [[ -n "$a" && -n "$b" && "$b" -gt 0 ]] && echo "  p50 ratio to the bare pty's floor: $(awk -v a="$a" -v b="$b" 'BEGIN{printf "%.2f", a/b}')"
  kill -INT $pid; wait $pid || true
}

# The floor: the same client against a bare pty echo (tools/bench/pty_echo), then robuterd.
echo_pty="$dir/echo.pty"
"$bin/robuter_pty_echo" "$echo_pty" &
echo_pid=$!
for _ in $(seq 100); do [[ -L "$echo_pty" ]] && break; sleep 0.05; done
echo -n "bare pty echo (floor), SCHED_OTHER: "
floor=$("$bin/robuterctl" --port "$echo_pty" --bench "$n" --bench-line BO)
echo "$floor"
kill -INT $echo_pid; wait $echo_pid || true
p50() { sed -n 's/.*p50 \([0-9]*\) us.*/\1/p' <<<"$1"; }

run_case "robuterd --sim, 10 ms tick, pty, SCHED_OTHER" ""
if chrt -f 70 true 2>/dev/null; then
  printf '[kernel]\nrealtime = true\nrt_priority = 80\nlock_memory = true\n' >"$dir/rt.toml"
  run_case "robuterd --sim, 10 ms tick, pty, SCHED_FIFO (server 80, client 70)" "$dir/rt.toml" chrt -f 70
fi
echo "target: p99 under 1000 us"

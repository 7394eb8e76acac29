#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Kernel figures: real-clock tick lateness of robuterd beside cyclictest at the same period,
# robuterd's resident memory after a minute, and the kernel's own per-tick cost.
set -euo pipefail
bin=${ROBUTER_BIN:-build/bin}
seconds=${ROBUTER_BENCH_KERNEL_SECONDS:-60}
ticks=$((seconds * 100))

stats=$(mktemp); trap 'rm -f "$stats"' EXIT

# cyclic LABEL [cyclictest options...]: 1000 wake-ups at 10 ms, lateness p50/p99/max from its histogram.
cyclic() {
  local label=$1; shift
  local hist; hist=$(mktemp)
  cyclictest -t1 "$@" -i 10000 -l 1000 -q -h 10000 >"$hist" 2>/dev/null || true
  awk -v label="$label" '
    /^[0-9]+/ { us=$1+0; n=$2+0; cnt[us]=n; total+=n; if (n>0) last=us }
    /# Max Latencies/ { mx=$4+0 }
    END {
      if (total == 0) { print label ": no samples"; exit }
      s=0; p50=-1; p99=-1
      for (u=0; u<=last; u++) { s+=cnt[u]; if (p50<0 && s>=0.5*total) p50=u; if (p99<0 && s>=0.99*total) p99=u }
      printf "%s: %d samples, lateness p50 %d us, p99 %d us, max %d us\n", label, total, p50, p99, mx
    }' "$hist"
  rm -f "$hist"
}
"$bin/robuterd" --sim --sonar-model ideal --ticks "$ticks" --stats --log-level warn >"$stats" 2>&1 &
pid=$!
sleep $((seconds - 2))
rss_kb=$(awk '/VmRSS/ {print $2}' /proc/$pid/status)
hwm_kb=$(awk '/VmHWM/ {print $2}' /proc/$pid/status)
wait $pid
line=$(grep '^tick ' "$stats")
echo "robuterd --sim (whole firmware), 10 ms tick, ${seconds} s, SCHED_OTHER: $line"
echo "robuterd resident memory after $((seconds - 2)) s: $((rss_kb / 1024)).$(( (rss_kb % 1024) * 10 / 1024 )) MB (peak $((hwm_kb / 1024)).$(( (hwm_kb % 1024) * 10 / 1024 )) MB; target < 20 MB)"

if command -v cyclictest >/dev/null; then
  cyclic "cyclictest, 10 ms interval, 10 s, SCHED_OTHER"
else
  echo "cyclictest: not installed (apt-get install rt-tests) — no peer figure"
fi

# The same pair with SCHED_FIFO and locked memory, as on the robot (needs root or CAP_SYS_NICE).
rt_cfg=$(mktemp --suffix=.toml)
printf '[kernel]\nrealtime = true\nrt_priority = 80\nlock_memory = true\n' >"$rt_cfg"
if "$bin/robuterd" --sim --sonar-model ideal --config "$rt_cfg" --ticks 1000 --stats --log-level warn >"$stats" 2>&1 && ! grep -q refused "$stats"; then
  echo "robuterd --sim, SCHED_FIFO 80, mlockall, 10 s: $(grep '^tick ' "$stats")"
  if command -v cyclictest >/dev/null; then
    cyclic "cyclictest, SCHED_FIFO 80, mlockall, 10 ms, 10 s" -p 80 -m
  fi
else
  echo "SCHED_FIFO not permitted here: $(grep -m1 refused "$stats" || echo 'robuterd failed')"
fi
rm -f "$rt_cfg"

if [[ -x "$bin/bench_kernel" ]]; then
  "$bin/bench_kernel" --benchmark_min_time=0.2 2>/dev/null | grep -E '^(BM_|-|Benchmark)'
fi

#!/usr/bin/env bash
# Link figures: pty round-trip latency of BO over 10,000 requests with the 10 ms tick running.
set -euo pipefail
bin=${ROBUTER_BIN:-build/bin}
n=${ROBUTER_BENCH_LINK_REQUESTS:-10000}
dir=$(mktemp -d); pty="$dir/robuter.pty"
"$bin/robuterd" --sim --pty "$pty" --log-level warn >"$dir/log" 2>&1 &
pid=$!
trap 'kill -INT $pid 2>/dev/null; wait $pid 2>/dev/null; rm -rf "$dir"' EXIT
for _ in $(seq 100); do [[ -L "$pty" ]] && break; sleep 0.05; done
echo -n "robuterd --sim, 10 ms tick, pty: "
"$bin/robuterctl" --port "$pty" --bench "$n" --bench-line BO
echo "target: p99 under 1000 us"

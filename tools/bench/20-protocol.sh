#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Bench section 20: protocol codec throughput (lines/s) on a realistic command mix.
set -euo pipefail
bin=${ROBUTER_BIN:-build/bin}/bench_protocol
if [[ ! -x "$bin" ]]; then
  echo "bench_protocol not built ($bin); configure with -DROBUTER_BENCH=ON" >&2
  exit 1
fi
json=$(mktemp)
trap 'rm -f "$json"' EXIT
"$bin" --benchmark_min_time=0.5 --benchmark_format=json >"$json"
python3 - "$json" <<'PY'
import json, sys
names = {
    "BM_Decode": "decoder (decode only)",
    "BM_FrameAndDecode": "decoder (framing + decode)",
    "BM_LinkCodec": "whole line path (framing, decode, port, reply)",
}
for b in json.load(open(sys.argv[1]))["benchmarks"]:
    label = names.get(b["name"], b["name"])
    print(f"{label:48s} {b['items_per_second'] / 1e6:8.2f} M lines/s")
PY

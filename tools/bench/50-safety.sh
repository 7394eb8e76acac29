#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Safety figures: range read to zero speed at the drive (seeded trials), ring latency and stopped
# full-scan time before/after the watch schedule, then the random-sequence property of
# docs/SAFETY.md §12–§13 at bench size (10,000 sequences; make test runs 2,000), once per sonar
# model of the noisy half (ROBUTER_BENCH_SAFETY_SONAR, default "stress realistic": the project's
# first noise and the realistic model, issue #19); then the multipath census.
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
rule=${ROBUTER_EMERGENCY_RULE:-envelope}
# The shards run as separate processes, in parallel; each prints its figures, then the totals.
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
status=0
for model in ${ROBUTER_BENCH_SAFETY_SONAR:-stress realistic}; do
echo "50-safety: random sequences, $rule rule, $sequences sequences (4 shards, in parallel), noisy half: the $model sonar model"
pids=()
for shard in 0 1 2 3; do
  ROBUTER_EMERGENCY_RULE=$rule ROBUTER_SAFETY_SIM_SEQUENCES=$sequences ROBUTER_SAFETY_SIM_SONAR=$model \
    "$bin/safety_sim_test" --gtest_filter="Shards/RandomSequences.*/$shard" >"$out/$shard.log" 2>&1 &
  pids+=($!)
done
for pid in "${pids[@]}"; do wait "$pid" || status=1; done
cat "$out"/[0-3].log | grep -v '^\[\|^Running main\|^Note: Google Test filter' || true
# Totals over the shards, from the per-shard lines.
awk 'BEGIN { closest = -1 }
     /^shard [0-9]\/[0-9] / { seq += $5; x = $7; gsub(/\(/, "", x); noisy += x }
     /sequences with a contact while the sonar watched/ {
       split($0, f, "watched: "); split(f[2], g, ";"); contacts += g[1]
       split($0, h, "sonar on "); c = h[2] + 0; if (closest < 0 || c < closest) closest = c }
     END { printf "50-safety: total %d sequences (%d with noise, the " model " sonar model), %d with a contact while the sonar watched, " \
                  "closest approach with the sonar on %d mm\n", seq, noisy, contacts, closest }' model="$model" \
  "$out"/[0-3].log
done
# Multipath against the evidence grid (docs/SAFETY.md §13, "Multipath"): a wanderer's realistic
# ring for 1,800 s (make test: 240 s), the cells of real surfaces that bounced echoes clear, the
# rule before and the rule now.
echo "50-safety: multipath census, ${ROBUTER_BENCH_MULTIPATH_SECONDS:-1800} s per world"
ROBUTER_MULTIPATH_SECONDS=${ROBUTER_BENCH_MULTIPATH_SECONDS:-1800} "$bin/safety_sim_test" --gtest_filter='Multipath.*' \
  | grep '^multipath' || status=1
exit $status

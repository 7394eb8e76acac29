#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Issue #18's acceptance through the whole firmware (docs/LOCALISATION.md, "Through the firmware"):
# 1. issue #17's ten routes (tools/bench/70-places.sh) with the simulator's odometry noise on,
#    without and with [localise] enabled (one repeat each: the ends, not the activations);
# 2. the building floor's corridor loop driven by an operator's client for 30 minutes, odometry
#    noise on and the realistic sonar model (issue #19's), then ideal sonars: the map pose's error
#    next to the odometry's;
# 3. ten kidnappings at seeded places: carried 3 m along the loop (back for an even seed, on for
#    an odd one) at 60 + 41 (seed - 1) s, not told; found = the map pose within 0.2 m and 10° for
#    2 s running, within 30 s of the carry.
# ROBUTER_BENCH_LOCALISE_TOUR_SECONDS (1800), ROBUTER_BENCH_LOCALISE_KIDNAPS (10).
set -uo pipefail
bin=${ROBUTER_BIN:-build/bin}
here=$(cd "$(dirname "$0")" && pwd)
prog="$bin/robuter_localise_firmware_bench"
if [[ ! -x "$prog" ]]; then
  echo "81-localise-firmware: $prog not built (make bench builds it)" >&2
  exit 1
fi
echo "--- #17's routes, odometry noise on, no localisation"
ROBUTER_BENCH_PLACES_REPEATS=1 ROBUTER_BENCH_PLACES_ODOMETRY_NOISE=1 bash "$here/70-places.sh" | head -12
echo "--- #17's routes, odometry noise on, [localise] enabled (target: 10 of 10)"
ROBUTER_BENCH_PLACES_REPEATS=1 ROBUTER_BENCH_PLACES_ODOMETRY_NOISE=1 ROBUTER_BENCH_PLACES_LOCALISE=1 bash "$here/70-places.sh" | head -12
echo "--- #17's routes, ideal odometry, [localise] enabled"
ROBUTER_BENCH_PLACES_REPEATS=1 ROBUTER_BENCH_PLACES_LOCALISE=1 bash "$here/70-places.sh" | head -12
seconds=${ROBUTER_BENCH_LOCALISE_TOUR_SECONDS:-1800}
echo "--- tour, ${seconds} s, odometry noise, realistic sonars (target: map pose p95 <= 100 mm and 3 deg)"
for seed in 1 2 3; do "$prog" tour "$seconds" "$seed"; done
echo "--- tour, ${seconds} s, odometry noise, ideal sonars"
for seed in 1 2 3; do ROBUTER_TOUR_SONAR=ideal "$prog" tour "$seconds" "$seed"; done
kidnaps=${ROBUTER_BENCH_LOCALISE_KIDNAPS:-10}
for sonar in realistic ideal; do
  found=0
  for ((seed = 1; seed <= kidnaps; seed++)); do
    line=$(ROBUTER_TOUR_SONAR=$sonar "$prog" kidnap 30 "$seed")
    echo "$line ($sonar sonar)"
    [[ $line == *"found after -1.0 s"* ]] || found=$((found + 1))
  done
  echo "kidnappings found within 30 s, $sonar sonar: $found of $kidnaps (target: 9 of 10)"
done

#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Serial re-open figures: a pty standing in for a USB serial adapter is removed and restored 20
# times under a running robuterd; time from the device being back to the link answering.
set -euo pipefail
bin=${ROBUTER_BIN:-build/bin}
here=$(cd "$(dirname "$0")" && pwd)
n=${ROBUTER_BENCH_REPLUG_CYCLES:-20}
python3 "$here/serial_replug.py" "$bin/robuterd" 500 "$n"
python3 "$here/serial_replug.py" "$bin/robuterd" 100 "$n"
echo "target: under retry_ms + one tick (10 ms), never a missed return"

#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# robuterd --sim on the default configuration, planning a 5.4 m goal: its peak RSS (VmHWM, as
# `--stats` prints it at exit) must stay within LIMIT kB (issue #16: 20 MB). Normal build only.
# usage: peak_memory.sh ROBUTERD LIMIT_KB
bin=${1:?usage: peak_memory.sh ROBUTERD LIMIT_KB}
limit=${2:?usage: peak_memory.sh ROBUTERD LIMIT_KB}
out=$(printf 'XG 50000 20000\r' | "$bin" --sim --sonar-model ideal --speed max --ticks 2000 --stats --stdio --log-level info 2>&1)
if ! printf '%s\n' "$out" | grep -aq 'planner: plan 1: path'; then
  printf '%s\n' "$out" | tail -20
  echo "FAIL: robuterd made no plan for XG 50000 20000"
  exit 1
fi
kb=$(printf '%s\n' "$out" | sed -n 's/.*peak memory (VmHWM) \([0-9][0-9]*\) kB.*/\1/p' | tail -1)
if [ -z "$kb" ]; then
  echo "FAIL: --stats printed no peak memory line"
  exit 1
fi
echo "robuterd --sim, default configuration, one plan: peak RSS $kb kB (limit $limit kB)"
[ "$kb" -le "$limit" ] || { echo "FAIL: $kb kB > $limit kB"; exit 1; }

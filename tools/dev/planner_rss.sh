#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Peak RSS (VmHWM) of robuterd on the simulator while its planner serves a goal.
# usage: tools/dev/planner_rss.sh ROBUTERD [GOAL_X GOAL_Y [TICKS]] — goal in 0.1 mm, odometry
# frame (docs/PROTOCOL.md, XG); prints the replies to XG and XP, then VmHWM in kB.
bin=${1:?usage: planner_rss.sh ROBUTERD [GOAL_X GOAL_Y [TICKS]]}
gx=${2:-50000}
gy=${3:-20000}
ticks=${4:-3000}
dir=$(mktemp -d)
mkfifo "$dir/in"
"$bin" --sim --sonar-model ideal --speed max --ticks "$ticks" --log-level off --stdio <"$dir/in" >"$dir/out" 2>&1 &
pid=$!
# The link stays open while the simulation runs: the goal first, the status a little later.
{ echo "XG $gx $gy"; sleep 1; echo "XP"; while kill -0 "$pid" 2>/dev/null; do sleep 0.2; done; } >"$dir/in" &
m=0
while kill -0 "$pid" 2>/dev/null; do
  v=$(awk '/VmHWM/{print $2}' "/proc/$pid/status" 2>/dev/null)
  [ -n "$v" ] && m=$v
  sleep 0.02
done
wait
tr '\r' '\n' <"$dir/out" | grep -E '^(ack|error|P )' | head -5
rm -rf "$dir"
echo "VmHWM $m kB"

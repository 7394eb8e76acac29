#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs one conformance script against a live `robuterd --sim --pty`, then checks robuterd
# stopped cleanly (exit 0): after SIGINT, or by itself when the script ends with AX.
set -u
robuterd=$1; robuterctl=$2; script=$3; shift 3
dir=$(mktemp -d); pty="$dir/robuter.pty"; log="$dir/robuterd.log"
trap 'kill -9 $pid 2>/dev/null; rm -rf "$dir"' EXIT
"$robuterd" --sim --sonar-model ideal --pty "$pty" --log-level warn "$@" >"$log" 2>&1 &
pid=$!
for _ in $(seq 100); do [[ -L "$pty" ]] && break; sleep 0.05; done
[[ -L "$pty" ]] || { echo "robuterd did not create $pty"; cat "$log"; exit 1; }
"$robuterctl" --port "$pty" --script "$script"; status=$?
if grep -q '^> AX' "$script"; then
  for _ in $(seq 100); do kill -0 $pid 2>/dev/null || break; sleep 0.05; done
  if kill -0 $pid 2>/dev/null; then echo "FAIL robuterd still running after AX"; status=1; fi
else
  kill -INT $pid
fi
wait $pid; rc=$?
if [[ $rc -ne 0 ]]; then echo "FAIL robuterd exited $rc"; cat "$log"; status=1; fi
if [[ -L "$pty" ]]; then echo "FAIL the pty link was not removed"; status=1; fi
exit $status

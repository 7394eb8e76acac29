#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Drives robuterd's pty with a third-party client from Debian (python3-serial).
set -u
robuterd=$1; client=$2
dir=$(mktemp -d); pty="$dir/robuter.pty"
trap 'kill -9 $pid 2>/dev/null; rm -rf "$dir"' EXIT
"$robuterd" --sim --sonar-model ideal --pty "$pty" --log-level warn >"$dir/log" 2>&1 &
pid=$!
for _ in $(seq 100); do [[ -L "$pty" ]] && break; sleep 0.05; done
/usr/bin/python3 "$client" "$pty"; status=$?
kill -INT $pid; wait $pid || { echo "FAIL robuterd exit $?"; status=1; }
exit $status

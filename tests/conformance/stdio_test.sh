#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Standard input/output transport: requests piped in, replies on stdout, AX ends it with status 0.
set -u
robuterd=$1
out=$(printf 'BT\rUN\rAM 10\rAX\r' | timeout 10 "$robuterd" --sim --sonar-model ideal --stdio --log-level warn 2>/dev/null); rc=$?
want=$'T 33\rN 3\rerror\rack\r'
if [[ $rc -ne 0 || "$out" != "$want" ]]; then
  echo "FAIL rc=$rc out=$(printf '%q' "$out")"; echo "0 passed, 1 failed"; exit 1
fi
# Read-your-writes through a pipe: BO waits for ASN's owner, AX after it; standard input's EOF
# comes before they are handled, their replies still go out.
out=$(printf 'ASN\rBO\rAC 5 6 7\rBO\rAX\r' | timeout 10 "$robuterd" --sim --sonar-model ideal --stdio --log-level warn 2>/dev/null); rc=$?
if [[ $rc -eq 0 && "$out" =~ ^ack$'\r'S\ [0-9-]+\ [0-9-]+\ [0-9-]+\ 1\ [0-9]+$'\r'ack$'\r'S\ 5\ 6\ 7\ 1\ [0-9]+$'\r'ack$'\r'$ ]]; then
  echo "2 passed, 0 failed"; exit 0
fi
echo "FAIL (read-your-writes) rc=$rc out=$(printf '%q' "$out")"; echo "1 passed, 1 failed"; exit 1

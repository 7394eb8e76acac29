#!/usr/bin/env bash
# Standard input/output transport: requests piped in, replies on stdout, AX ends it with status 0.
set -u
robuterd=$1
out=$(printf 'BT\rUN\rAM 10\rAX\r' | timeout 10 "$robuterd" --sim --stdio --log-level warn 2>/dev/null); rc=$?
want=$'T 33\rN 3\rerror\rack\r'
if [[ $rc -eq 0 && "$out" == "$want" ]]; then echo "1 passed, 0 failed"; exit 0; fi
echo "FAIL rc=$rc out=$(printf '%q' "$out")"; echo "0 passed, 1 failed"; exit 1

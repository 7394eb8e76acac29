#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# robuterd's command line: bad configurations exit 2 with one clear line; SIGINT stops it cleanly.
set -u
bin=$1; configs=$2
pass=0; fail=0
check() {  # name, expected exit, expected text, command...
  local name=$1 want_rc=$2 want=$3; shift 3
  local out rc
  out=$("$@" 2>&1); rc=$?
  if [[ $rc -eq $want_rc && "$out" == *"$want"* && $(printf '%s\n' "$out" | wc -l) -eq 1 ]]; then
    pass=$((pass+1)); echo "ok   $name: $out"
  else
    fail=$((fail+1)); echo "FAIL $name: rc=$rc (want $want_rc) out=[$out] want=[$want]"
  fi
}
check missing-file 2 "configuration error: /nope.toml: cannot open: No such file or directory" "$bin" --config /nope.toml --check-config
check unknown-key 2 "unknown_key.toml:2: key 'kernel.tik_us': unknown key" "$bin" --config "$configs/unknown_key.toml"
check wrong-type 2 "wrong_type.toml:2: key 'sonar.timeout_ms': expected an integer, got a string" "$bin" --config "$configs/wrong_type.toml"
check out-of-range 2 "out_of_range.toml:2: key 'kernel.tick_us': 50 is out of range 100..1000000" "$bin" --config "$configs/out_of_range.toml"
check unknown-process 2 "unknown_process.toml:1: key 'process.teleport': no process of that name" "$bin" --sim --config "$configs/unknown_process.toml"
check bad-row 2 "offset 10 must be less than the period 10" "$bin" --sim --config "$configs/bad_row.toml"
check syntax 2 "syntax.toml:1:" "$bin" --config "$configs/syntax.toml"
check valid 0 "is valid" "$bin" --check-config
check bad-world-toml 2 "world: $configs/bad_world.toml:5: [start]: y: expected a number" "$bin" --sim --world "$configs/bad_world.toml" --ticks 1
check bad-world-env 2 "world: $configs/bad_world.env:2: bad count" "$bin" --sim --world "$configs/bad_world.env" --ticks 1
check missing-world 2 "world: /nope.toml: cannot open" "$bin" --sim --world /nope.toml --ticks 1
check bad-speed 2 "--speed 'fast': expected a positive number or 'max'" "$bin" --sim --speed fast
check bad-sonar-model 2 "--sonar-model 'perfect': expected ideal, stress or realistic" "$bin" --sim --sonar-model perfect --ticks 1
check sonar-model-runs 0 "" "$bin" --sim --sonar-model realistic --ticks 200 --log-level off
# The simulator's sonars are realistic unless a harness says otherwise (issue #19).
for want in "realistic:" "ideal:--sonar-model ideal" "stress:--sonar-noise"; do
  out=$("$bin" --sim --ticks 1 --log-level info ${want#*:} 2>&1 | grep 'sim: sonar model')
  if [[ "$out" == *"sim: sonar model ${want%%:*} "* ]]; then pass=$((pass+1)); echo "ok   sonar-model-${want%%:*}: $out"
  else fail=$((fail+1)); echo "FAIL sonar-model-${want%%:*}: [$out]"; fi
done
check sonar-noise-and-model 2 "--sonar-noise is --sonar-model stress: give one of them" "$bin" --sim --sonar-noise --sonar-model ideal --ticks 1

# Inputs that are not what they should be (issue #14): folders, devices and oversize files are
# refused with a reason; process-table errors name the key's file and line; a tick of 100 µs
# (the documented minimum) runs; one link per pty path.
tmpdir=$(mktemp -d)
truncate -s 2M "$tmpdir/big.toml"
check folder-config 2 "configuration error: $tmpdir: is a folder, not a file" "$bin" --check-config --config "$tmpdir"
check dev-zero-config 2 "configuration error: /dev/zero: is a character device, not a regular file" "$bin" --check-config --config /dev/zero
check big-config 2 "configuration error: $tmpdir/big.toml: is larger than 1 MB (2097152 bytes)" "$bin" --check-config --config "$tmpdir/big.toml"
check folder-world 2 "world: $tmpdir: is a folder, not a file" "$bin" --sim --world "$tmpdir" --ticks 1
check dev-zero-world 2 "world: /dev/zero: is a character device, not a regular file" "$bin" --sim --world /dev/zero --ticks 1
check bad-row-line 2 "bad_row.toml:3: key 'process.heartbeat.offset': offset 10 must be less than the period 10" "$bin" --sim --config "$configs/bad_row.toml"
check bad-budget-line 2 "bad_budget.toml:3: key 'process.heartbeat.budget_us': budget 200000 µs exceeds the period of 100000 µs" "$bin" --sim --config "$configs/bad_budget.toml"
check small-tick-valid 0 "is valid" "$bin" --check-config --config "$configs/small_tick.toml"
check small-tick-runs 0 "" "$bin" --sim --sonar-model ideal --config "$configs/small_tick.toml" --ticks 200 --log-level off
check pty-twice 2 "--pty $tmpdir/./x.pty: given twice (one link per path)" "$bin" --sim --pty "$tmpdir/x.pty" --pty "$tmpdir/./x.pty" --ticks 1
out=$("$bin" --sim --sonar-model ideal --planner-pictures "$tmpdir/pictures/new" --ticks 5 --log-level info 2>&1); rc=$?
if [[ $rc -eq 0 && -d "$tmpdir/pictures/new" && "$out" == *"planner: --planner-pictures $tmpdir/pictures/new did not exist: created it"* ]]; then
  pass=$((pass+1)); echo "ok   planner-pictures-created: said so"
else fail=$((fail+1)); echo "FAIL planner-pictures-created: rc=$rc out=[$out]"; fi
touch "$tmpdir/a-file"
check planner-pictures-file 2 "--planner-pictures $tmpdir/a-file: exists and is not a folder" "$bin" --sim --planner-pictures "$tmpdir/a-file" --ticks 1
rm -rf "$tmpdir"

# Hardware backends (docs/CAN.md): without AF_CAN in the kernel the CAN backend fails at start-up
# naming the missing family; with it, the missing interface is named.
check no-backend 2 "no hardware backend configured" "$bin" --ticks 1
check can-same-node 2 "can_same_node.toml:3: key 'can.right_node': 3 is also can.left_node" "$bin" --config "$configs/can_same_node.toml"
check bad-hardware 2 "bad_hardware.toml:2: key 'hardware.drive': 'ethercat' is not one of: none, can" "$bin" --config "$configs/bad_hardware.toml"
if python3 -c 'import socket; socket.socket(socket.PF_CAN, socket.SOCK_RAW, socket.CAN_RAW)' 2>/dev/null; then
  check can-no-interface 2 "CAN interface 'robutercan9': if_nametoindex: No such device — no such network interface" "$bin" --config "$configs/can_hardware.toml" --ticks 1
else
  check can-no-af-can 2 "CAN interface 'robutercan9': socket(PF_CAN, SOCK_RAW, CAN_RAW): Address family not supported by protocol — this kernel has no SocketCAN (address family AF_CAN/PF_CAN missing)" "$bin" --config "$configs/can_hardware.toml" --ticks 1
fi

# SIGINT and SIGTERM: clean stop, exit status 0 (sent once robuterd says it is starting: the
# handlers are installed before that line).
log=$(mktemp)
"$bin" --sim --sonar-model ideal --log-level info >"$log" 2>&1 &
pid=$!
wait_started() { for _ in $(seq 600); do grep -q starting "$log" && return; sleep 0.05; done; }  # up to 30 s (sanitizers, loaded CI)
wait_started
kill -INT $pid; wait $pid; rc=$?
if [[ $rc -eq 0 ]] && grep -q "stopped after" "$log"; then pass=$((pass+1)); echo "ok   sigint: exit 0"; else fail=$((fail+1)); echo "FAIL sigint: rc=$rc"; cat "$log"; fi
"$bin" --sim --sonar-model ideal --log-level info >"$log" 2>&1 &
pid=$!
wait_started; kill -TERM $pid; wait $pid; rc=$?
if [[ $rc -eq 0 ]]; then pass=$((pass+1)); echo "ok   sigterm: exit 0"; else fail=$((fail+1)); echo "FAIL sigterm: rc=$rc"; fi
rm -f "$log"
echo "$pass passed, $fail failed"
[[ $fail -eq 0 ]]

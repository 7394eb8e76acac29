#!/usr/bin/env bash
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
"$bin" --sim --log-level info >"$log" 2>&1 &
pid=$!
wait_started() { for _ in $(seq 600); do grep -q starting "$log" && return; sleep 0.05; done; }  # up to 30 s (sanitizers, loaded CI)
wait_started
kill -INT $pid; wait $pid; rc=$?
if [[ $rc -eq 0 ]] && grep -q "stopped after" "$log"; then pass=$((pass+1)); echo "ok   sigint: exit 0"; else fail=$((fail+1)); echo "FAIL sigint: rc=$rc"; cat "$log"; fi
"$bin" --sim --log-level info >"$log" 2>&1 &
pid=$!
wait_started; kill -TERM $pid; wait $pid; rc=$?
if [[ $rc -eq 0 ]]; then pass=$((pass+1)); echo "ok   sigterm: exit 0"; else fail=$((fail+1)); echo "FAIL sigterm: rc=$rc"; fi
rm -f "$log"
echo "$pass passed, $fail failed"
[[ $fail -eq 0 ]]

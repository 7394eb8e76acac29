#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# robuterd with serial and GPIO configuration: devices named but absent pass --check-config and
# stop a start with one clear line; a bad key names file:line; SIGTERM with a serial link open.
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
check check-config-names-not-opens 0 "is valid" "$bin" --config "$configs/robot.toml" --check-config
check missing-serial 2 "robuterd: serial link: cannot open /dev/robuter-test-missing-link: No such file or directory" \
  "$bin" --sim --config "$configs/robot.toml" --ticks 1
check missing-serial-cli 2 "serial link: cannot open /dev/robuter-test-nope: No such file or directory" \
  "$bin" --sim --serial /dev/robuter-test-nope --ticks 1
check missing-gpio-chip 2 "gpio_only.toml:3: gpio: cannot open chip /dev/gpiochip-robuter-test: No such file or directory" \
  "$bin" --sim --config "$configs/gpio_only.toml" --ticks 1
check bad-parity 2 "bad_parity.toml:2: key 'links.serial.parity': 'mark' is not one of: none, even, odd" \
  "$bin" --config "$configs/bad_parity.toml" --check-config
check bad-baud 2 "--baud 1234: not a supported rate" "$bin" --sim --serial /dev/null --baud 1234 --ticks 1
check not-a-tty 2 "serial link: cannot open /dev/null: Inappropriate ioctl for device" "$bin" --sim --serial /dev/null --ticks 1

# SIGTERM while a serial link is open (its helper thread must not take the signal): exit 0.
log=$(mktemp); dir=$(mktemp -d)
python3 -c 'import os,pty,sys,time; m,s=pty.openpty(); os.symlink(os.ttyname(s), sys.argv[1]); time.sleep(120)' "$dir/dev" &
holder=$!
for _ in $(seq 50); do [[ -e "$dir/dev" ]] && break; sleep 0.1; done
"$bin" --sim --sonar-model ideal --serial "$dir/dev" --log-level info >"$log" 2>&1 &
pid=$!
for _ in $(seq 600); do grep -q starting "$log" && break; sleep 0.05; done  # up to 30 s (sanitizers, loaded CI)
kill -TERM $pid; wait $pid; rc=$?
if [[ $rc -eq 0 ]] && grep -q "stopped after" "$log"; then pass=$((pass+1)); echo "ok   sigterm-with-serial: exit 0"; else fail=$((fail+1)); echo "FAIL sigterm-with-serial: rc=$rc"; cat "$log"; fi
kill $holder 2>/dev/null; wait $holder 2>/dev/null
rm -rf "$log" "$dir"
echo "$pass passed, $fail failed"
[[ $fail -eq 0 ]]

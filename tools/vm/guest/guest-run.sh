#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later
# make test-vm, inside the guest (run by robuter-vm-run.service, output on the serial console):
# the system's facts, then the checks (guest-checks.py) against the package on the payload disk.
set -u
P=/mnt/payload
echo "vm: up: $(cut -d' ' -f1 /proc/uptime) s since the kernel started; PID 1 is $(cat /proc/1/comm);" \
     "$(systemctl --version | head -1); kernel $(uname -r)"
exec python3 "$P/guest-checks.py" "$P"

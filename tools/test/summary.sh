#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Adds up the ctest summaries of the given logs into one closing line: "N passed, N failed".
set -u
passed=0; failed=0
for log in "$@"; do
  line=$(grep -E '^[0-9]+% tests passed, [0-9]+ tests? failed out of [0-9]+' "$log" | tail -1)
  if [[ -z "$line" ]]; then echo "summary: no ctest summary in $log"; failed=$((failed + 1)); continue; fi
  f=$(sed -E 's/.* ([0-9]+) tests? failed out of ([0-9]+).*/\1/' <<<"$line")
  n=$(sed -E 's/.* failed out of ([0-9]+).*/\1/' <<<"$line")
  passed=$((passed + n - f)); failed=$((failed + f))
done
echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]

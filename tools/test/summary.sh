#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Adds up the ctest summaries of the given logs into one closing line: "N passed, N failed".
# Before it, each failed test's name and the end of its output: CI shows a log's tail only.
set -u
passed=0; failed=0
for log in "$@"; do
  line=$(grep -E '^[0-9]+% tests passed, [0-9]+ tests? failed out of [0-9]+' "$log" | tail -1)
  if [[ -z "$line" ]]; then echo "summary: no ctest summary in $log"; failed=$((failed + 1)); continue; fi
  f=$(sed -E 's/.* ([0-9]+) tests? failed out of ([0-9]+).*/\1/' <<<"$line")
  n=$(sed -E 's/.* failed out of ([0-9]+).*/\1/' <<<"$line")
  passed=$((passed + n - f)); failed=$((failed + f))
  # ctest --output-on-failure: a failed test's output follows its "Test #N: name ... ***" line,
  # up to the next "Start N:" or "k/n Test #" line. A disabled test ("***Not Run (Disabled)") has
  # not failed: ctest leaves it out of its own count too.
  awk -v logname="$log" '
    /^ *[0-9]+\/[0-9]+ Test +#[0-9]+: .*\*\*\*/ && !/\*\*\*Not Run \(Disabled\)/ { name = $4; n = 0; grab = 1; next }
    /^ *Start +[0-9]+: / || /^ *[0-9]+\/[0-9]+ Test +#/ || /^[0-9]+% tests passed/ {
      if (grab) { print "summary: FAILED " name " (" logname "), its output'"'"'s last lines:";
                  s = n > 40 ? n - 40 : 0; for (i = s + 1; i <= n; ++i) print "  | " buf[i] }
      grab = 0; next }
    grab { buf[++n] = $0 }
  ' "$log"
done
echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]

#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs every protocol fuzz target: run.sh [SECONDS | -runs=N | --short]  (default 60 s each).
# Seeds come from tools/fuzz/corpus/<target>/; new inputs go to build-fuzz/corpus/<target>/.
# Ends with one line per target: "<target>: <N> executions in <S> s".
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
out=${ROBUTER_FUZZ_BUILD:-$root/build-fuzz}
arg=${1:-60}
case "$arg" in
  --short) limit=(-max_total_time=10) ;;          # two targets, ~20 s in all
  -runs=*) limit=("$arg") ;;
  ''|*[!0-9]*) echo "usage: $0 [SECONDS | -runs=N | --short]" >&2; exit 2 ;;
  *) limit=(-max_total_time="$arg") ;;
esac
"$here/build.sh" >/dev/null
summary=()
status=0
for target in fuzz_decoder fuzz_line_handler; do
  work="$out/corpus/$target"
  mkdir -p "$work" "$out/artifacts/$target"
  log="$out/$target.log"
  if ! "$out/$target" "${limit[@]}" -max_len=1024 -dict="$here/protocol.dict" -print_final_stats=1 \
      -artifact_prefix="$out/artifacts/$target/" "$work" "$here/corpus/$target" >"$log" 2>&1; then
    echo "$target FAILED; see $log and $out/artifacts/$target/" >&2
    tail -30 "$log" >&2
    status=1
  fi
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  secs=$(sed -n 's/^Done [0-9]* runs in \([0-9]*\) second.*/\1/p' "$log" | tail -1)
  summary+=("$target: ${runs:-?} executions in ${secs:-?} s")
done
printf '%s\n' "${summary[@]}"
exit $status

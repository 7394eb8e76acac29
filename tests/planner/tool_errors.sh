#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# robuter-plan with broken input files: each run must fail with exit status 1 and one clear
# "file:line: message" error, print no plan, and write nothing (no picture, no saved map).
set -u
tool=$1; data=$2; good=$3
out=$(mktemp -d); trap 'rm -rf "$out"' EXIT
status=0
# expect NAME REGEX ARGS...: exit 1, stderr matches REGEX, stdout empty, nothing written in $out.
expect() {
  local name=$1 regex=$2; shift 2
  "$tool" "$@" -o "$out/plan.png" --save-map "$out/saved.map" >"$out/stdout" 2>"$out/stderr"
  local rc=$?
  local err; err=$(cat "$out/stderr")
  if [[ $rc -ne 1 ]]; then echo "FAIL $name: exit $rc, expected 1 ($err)"; status=1; fi
  if ! grep -Eq "$regex" "$out/stderr"; then echo "FAIL $name: error '$err' does not match '$regex'"; status=1; fi
  if [[ $(wc -l <"$out/stderr") -ne 1 ]]; then echo "FAIL $name: expected one error line, got: $err"; status=1; fi
  if [[ -s "$out/stdout" ]]; then echo "FAIL $name: printed $(cat "$out/stdout")"; status=1; fi
  if [[ -e "$out/plan.png" || -e "$out/saved.map" ]]; then echo "FAIL $name: wrote a file"; status=1; fi
  rm -f "$out/plan.png" "$out/saved.map" "$out/stdout" "$out/stderr"
  [[ $status -eq 0 ]] && echo "ok   $name: $err"
}
# expect_movingai NAME REGEX MAP SCEN (no -o / --save-map: the mode writes nothing anyway).
expect_movingai() {
  local name=$1 regex=$2; shift 2
  "$tool" --movingai "$@" >"$out/stdout" 2>"$out/stderr"; local rc=$?
  local err; err=$(cat "$out/stderr")
  if [[ $rc -ne 1 ]] || ! grep -Eq "$regex" "$out/stderr" || [[ -s "$out/stdout" ]]; then
    echo "FAIL $name: exit $rc, stderr '$err', stdout $(wc -c <"$out/stdout") bytes"; status=1
  else echo "ok   $name: $err"; fi
}
expect params-missing-number "missing_number\.params:[0-9]+: " -p "$data/missing_number.params" -a "$good/lab.env"
expect env-not-a-number "not_a_number\.env:5: " -p "$good/lab.params" -a "$data/not_a_number.env"
expect saved-map-bad-cell "bad_cell\.map:9: bad cell" -p "$good/lab.params" -s "$data/bad_cell.map"
expect world-bad-start "bad_start\.toml:6: " -w "$data/bad_start.toml"
expect world-missing "nope\.toml: cannot open" -w "$data/nope.toml"
expect env-missing "nope\.env: " -p "$good/lab.params" -a "$data/nope.env"
expect_movingai movingai-short-row "short_row\.map:6: " "$data/short_row.map" "$data/few_fields.scen"
expect_movingai movingai-few-fields "few_fields\.scen:3: expected 9 fields" "$data/ok.map" "$data/few_fields.scen"
exit $status

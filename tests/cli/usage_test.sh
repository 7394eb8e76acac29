#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# One program's command-line rule (cli/parse_or_usage.hpp): an unknown option exits STATUS with
# CLI11's two lines on stderr and nothing on stdout; --help exits 0 with the usage on stdout only.
# usage_test.sh PROGRAM STATUS [ARGS...]: ARGS, given before --bogus, are what the program requires
# (a required option or subcommand is reported before an unknown option).
set -u
bin=$1; status=$2; shift 2
out=$(mktemp -d); trap 'rm -rf "$out"' EXIT
fail=0
"$bin" "$@" --bogus </dev/null >"$out/stdout" 2>"$out/stderr"; rc=$?
want=$'The following argument was not expected: --bogus\nRun with --help for more information.'
if [[ $rc -ne $status ]]; then echo "FAIL --bogus: exit $rc, expected $status"; fail=1; fi
if [[ -s "$out/stdout" ]]; then echo "FAIL --bogus: printed on stdout: $(head -c 200 "$out/stdout")"; fail=1; fi
if [[ "$(cat "$out/stderr")" != "$want" ]]; then echo "FAIL --bogus: stderr [$(cat "$out/stderr")], expected [$want]"; fail=1; fi
[[ $fail -eq 0 ]] && echo "ok   --bogus: exit $rc, stderr: $(head -n 1 "$out/stderr")"
"$bin" --help </dev/null >"$out/stdout" 2>"$out/stderr"; rc=$?
if [[ $rc -ne 0 || -s "$out/stderr" ]] || ! grep -q "^Usage: .*$(basename "$bin") \[OPTIONS\]" "$out/stdout"; then
  echo "FAIL --help: exit $rc, stderr [$(cat "$out/stderr")], stdout $(wc -l <"$out/stdout") lines"; fail=1
else echo "ok   --help: exit 0, $(wc -l <"$out/stdout") lines on stdout, none on stderr"; fi
exit $fail

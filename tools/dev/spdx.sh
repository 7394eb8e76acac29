#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The licence line at the head of every tracked source file (GPL-3.0-or-later, LICENSE).
#   tools/dev/spdx.sh          adds it where it is missing (re-runnable: files that have it are left alone)
#   tools/dev/spdx.sh --check  lists the files without it and exits 1 (ctest licence.spdx); 77 outside a git tree
# C++ sources (*.cpp, *.hpp, *.h) take `// SPDX-License-Identifier: GPL-3.0-or-later`; CMake
# files, Makefile, debian/rules, Python and shell scripts take it after `#`. It goes on the first
# line, before the file's own header comment; after the `#!` line of a script. Data is left as it
# is: *.toml (worlds, configurations, test inputs whose errors cite line numbers), conformance
# scripts, fuzz corpus, docs, deploy/ and the rest of debian/.
set -euo pipefail
readonly LICENSE_ID="SPDX-License-Identifier: GPL-3.0-or-later"
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
check=0
case "${1:-}" in
  --check) check=1 ;;
  "") ;;
  *) echo "usage: $0 [--check]" >&2; exit 2 ;;
esac
if ! git -C "$root" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  echo "spdx: $root is not a git work tree: nothing to list" >&2
  exit 77
fi

# Sets m to the comment marker of a tracked file's SPDX line; empty when the file takes none.
# (No subshells here or in has_line: a fork per file made the check take seconds.)
marker() {
  case "$1" in
    *.cpp | *.hpp | *.h) m="//" ;;
    CMakeLists.txt | */CMakeLists.txt | *.cmake | Makefile | */Makefile | debian/rules | *.py | *.sh) m="#" ;;
    *) m="" ;;
  esac
}

# True when the file already says its licence in its first three lines.
has_line() {
  local line n=0
  while ((n < 3)) && { IFS= read -r line || [[ -n $line ]]; }; do
    [[ $line == *"SPDX-License-Identifier:"* ]] && return 0
    n=$((n + 1))
  done <"$1"
  return 1
}

# Writes the line in: second after a `#!` line, first otherwise. The file keeps its inode and mode.
add_line() {
  local file=$1 line="$2 $LICENSE_ID" tmp
  tmp=$(mktemp)
  if [[ $(head -c 2 -- "$file") == '#!' ]]; then
    { head -n 1 -- "$file"; printf '%s\n' "$line"; tail -n +2 -- "$file"; } >"$tmp"
  else
    { printf '%s\n' "$line"; cat -- "$file"; } >"$tmp"
  fi
  cat "$tmp" >"$file"
  rm -f "$tmp"
}

cd "$root"
total=0
changed=()
while IFS= read -r -d '' file; do
  marker "$file"
  [[ -n $m && -f $file ]] || continue
  total=$((total + 1))
  has_line "$file" && continue
  changed+=("$file")
  if ((check)); then
    echo "missing SPDX line: $file"
  else
    add_line "$file" "$m"
  fi
done < <(git ls-files -z)

if ((check)); then
  if ((${#changed[@]} > 0)); then
    echo "spdx: ${#changed[@]} of $total source files without '$LICENSE_ID' (tools/dev/spdx.sh adds it)"
    exit 1
  fi
  echo "spdx: all $total source files carry '$LICENSE_ID'"
else
  for f in "${changed[@]}"; do echo "added: $f"; done
  echo "spdx: the line added to ${#changed[@]} of $total source files"
fi

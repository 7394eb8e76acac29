#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs the missing Debian packages named in the given lists (as root), or says exactly what to install.
set -euo pipefail
native=$(dpkg --print-architecture)
missing=()
for list in "$@"; do
  while read -r pkg; do
    [[ -z "$pkg" || "$pkg" == \#* ]] && continue
    # One line per installed architecture: a name without ":arch" is the host's (or an
    # architecture-independent) package, whatever foreign-architecture copies are installed too.
    want=$native; [[ "$pkg" == *:* ]] && want=${pkg##*:}
    dpkg-query -W -f='${Architecture} ${Status}\n' "$pkg" 2>/dev/null |
      grep -Eq "^($want|all) install ok installed$" || missing+=("$pkg")
  done < "$list"
done
[[ ${#missing[@]} -eq 0 ]] && exit 0
if [[ $(id -u) -eq 0 ]]; then
  echo "deps: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  # A foreign architecture's index that fails to download (mirror sync) must not stop the install.
  apt-get update -qq || echo "deps: apt-get update reported errors; installing from the indexes there are" >&2
  # --no-remove: never take away an installed package to make room (a target -dev package that
  # is not co-installable with the host's, e.g. libserial-dev:arm64, would replace it).
  apt-get install -y -qq --no-install-recommends --no-remove "${missing[@]}"
else
  echo "deps: missing Debian packages. Install them with:" >&2
  echo "  sudo apt-get install ${missing[*]}" >&2
  exit 1
fi

#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds the protocol's libFuzzer targets with clang (the main g++ build cannot) into build-fuzz/.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${ROBUTER_FUZZ_BUILD:-$root/build-fuzz}
cxx=${CXX_FUZZ:-$(command -v clang++-14 || command -v clang++)}
flags=(-std=c++20 -O1 -g -fno-omit-frame-pointer -fsanitize=fuzzer,address,undefined
       -fno-sanitize-recover=undefined -I"$root" -Wall -Wextra -Werror)
mkdir -p "$out/obj"

# The codec once, as objects without the fuzzer main (fuzzer-no-link), then each target.
objs=()
for src in "$root"/protocol/codec/*.cpp; do
  obj="$out/obj/$(basename "${src%.cpp}").o"
  if [[ ! -e "$obj" || "$src" -nt "$obj" || -n "$(find "$root/protocol/codec" -name '*.hpp' -newer "$obj")" ]]; then
    "$cxx" "${flags[@]/-fsanitize=fuzzer,address,undefined/-fsanitize=fuzzer-no-link,address,undefined}" -c "$src" -o "$obj"
  fi
  objs+=("$obj")
done
for target in fuzz_decoder fuzz_line_handler; do
  "$cxx" "${flags[@]}" "$root/tools/fuzz/$target.cpp" "${objs[@]}" -o "$out/$target"
  echo "built $out/$target"
done

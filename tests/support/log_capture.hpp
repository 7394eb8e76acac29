// SPDX-License-Identifier: GPL-3.0-or-later
// What the log holds for a test: the records since the last call, read by pointing its sink at a file.
#pragma once

#include <cstdio>
#include <string>

#include "kernel/log.hpp"

namespace robuter::test {

// The records logged since the last call (or since the log started), as text; the log's sink is
// a temporary file while it drains, and the log is stopped afterwards, as log::stop() leaves it.
inline std::string log_since_last() {
  std::FILE* f = std::tmpfile();
  if (f == nullptr) return {};
  log::start(f);
  log::stop();
  std::rewind(f);
  std::string out;
  char buf[512];
  while (std::fgets(buf, sizeof buf, f)) out += buf;
  std::fclose(f);
  return out;
}

}  // namespace robuter::test

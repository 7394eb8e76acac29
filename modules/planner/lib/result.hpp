// SPDX-License-Identifier: GPL-3.0-or-later
// Error values and a small Result<T>: the planner library reports failures without exceptions.
#pragma once

#include <string>

#include "kernel/expected.hpp"

namespace robuter::plan {

// A failure that names where it happened (file and line when it comes from a file).
struct Error {
  std::string file;     // file the error is about; empty when not from a file
  int line = 0;         // 1-based line in that file; 0 when not applicable
  std::string message;  // what went wrong, for a human

  // Why: one printable form "file:line: message" for logs and tools.
  std::string text() const {
    if (file.empty()) return message;
    if (line <= 0) return file + ": " + message;
    return file + ":" + std::to_string(line) + ": " + message;
  }
};

// Either a value or an Error (kernel/expected.hpp).
template <class T>
using Result = Expected<T, Error>;

// A Result with no value: success or an Error.
struct Ok {};
using Status = Result<Ok>;

}  // namespace robuter::plan

// SPDX-License-Identifier: GPL-3.0-or-later
// Error values for the simulator's loaders: a message naming the file and line, never a throw.
#pragma once

#include <string>

#include "kernel/expected.hpp"

namespace robuter::sim {

// What went wrong while reading an input file, and where.
struct Error {
  std::string file;     // file name as given by the caller (or "<text>")
  int line = 0;         // 1-based line number; 0 when the error concerns the whole file
  std::string message;  // human-readable reason

  // "file:line: message", the form compilers use, so editors can jump to it.
  std::string describe() const {
    if (line > 0) return file + ":" + std::to_string(line) + ": " + message;
    return file + ": " + message;
  }
};

// Either a value or an Error (kernel/expected.hpp).
template <class T>
using Result = Expected<T, Error>;

// The value-less case: success, or an Error.
struct Ok {};
using Status = Result<Ok>;

}  // namespace robuter::sim

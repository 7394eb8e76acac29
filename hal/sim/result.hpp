// SPDX-License-Identifier: GPL-3.0-or-later
// Error values for the simulator's loaders: a message naming the file and line, never a throw.
#pragma once

#include <string>
#include <utility>
#include <variant>

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

// Either a value or an Error; C++20 has no std::expected yet.
template <class T>
class Result {
 public:
  Result(T value) : v_(std::move(value)) {}          // NOLINT: implicit on purpose
  Result(Error error) : v_(std::move(error)) {}      // NOLINT: implicit on purpose

  bool ok() const { return v_.index() == 0; }
  explicit operator bool() const { return ok(); }
  T& value() & { return std::get<0>(v_); }
  const T& value() const& { return std::get<0>(v_); }
  T&& value() && { return std::get<0>(std::move(v_)); }
  const Error& error() const { return std::get<1>(v_); }

 private:
  std::variant<T, Error> v_;  // the value, or why there is none
};

// The value-less case: success, or an Error.
struct Ok {};
using Status = Result<Ok>;

}  // namespace robuter::sim

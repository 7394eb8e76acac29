// SPDX-License-Identifier: GPL-3.0-or-later
// Error values and a small Result<T>: the planner library reports failures without exceptions.
#pragma once

#include <string>
#include <utility>
#include <variant>

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

// Either a value or an Error (std::expected is C++23; this is the part we need).
template <class T>
class Result {
 public:
  Result(T value) : v_(std::move(value)) {}        // NOLINT: implicit by design
  Result(Error error) : v_(std::move(error)) {}    // NOLINT: implicit by design

  bool ok() const { return v_.index() == 0; }
  explicit operator bool() const { return ok(); }
  T& value() { return std::get<0>(v_); }
  const T& value() const { return std::get<0>(v_); }
  T& operator*() { return value(); }
  const T& operator*() const { return value(); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  const Error& error() const { return std::get<1>(v_); }

 private:
  std::variant<T, Error> v_;
};

// A Result with no value: success or an Error.
struct Ok {};
using Status = Result<Ok>;

}  // namespace robuter::plan

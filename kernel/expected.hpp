// SPDX-License-Identifier: GPL-3.0-or-later
// Either a value or an error (std::expected is C++23; this is the part the file readers need).
#pragma once

#include <utility>
#include <variant>

namespace robuter {

// A value of type T, or the error E that stopped it. The simulator's and the planner's loaders
// name it Result<T> with their own Error (hal/sim/result.hpp, modules/planner/lib/result.hpp).
template <class T, class E>
class Expected {
 public:
  Expected(T value) : v_(std::move(value)) {}        // NOLINT: implicit on purpose
  Expected(E error) : v_(std::move(error)) {}        // NOLINT: implicit on purpose

  bool ok() const { return v_.index() == 0; }
  explicit operator bool() const { return ok(); }
  T& value() & { return std::get<0>(v_); }
  const T& value() const& { return std::get<0>(v_); }
  T&& value() && { return std::get<0>(std::move(v_)); }
  T& operator*() { return std::get<0>(v_); }
  const T& operator*() const { return std::get<0>(v_); }
  T* operator->() { return &std::get<0>(v_); }
  const T* operator->() const { return &std::get<0>(v_); }
  const E& error() const { return std::get<1>(v_); }

 private:
  std::variant<T, E> v_;  // the value, or why there is none
};

}  // namespace robuter

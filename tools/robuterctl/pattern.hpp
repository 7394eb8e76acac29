// SPDX-License-Identifier: GPL-3.0-or-later
// Reply patterns of conformance scripts: literal text with {int}, {int:a..b}, {ints:N}, {word}, {any}.
#pragma once

#include <optional>
#include <regex>
#include <string>
#include <vector>

namespace robuter::ctl {

class Pattern {
 public:
  // Compiles `text`; error() says what is wrong with it.
  explicit Pattern(const std::string& text);
  const std::optional<std::string>& error() const { return error_; }
  // True when `line` matches whole, with every ranged integer within its range.
  bool matches(const std::string& line) const;
  const std::string& text() const { return text_; }

 private:
  struct Range {
    long long lo, hi;  // inclusive bounds of a captured integer
  };
  std::string text_;                  // the pattern as written
  std::regex re_;                     // compiled form
  std::vector<std::optional<Range>> groups_;  // per capture group, its range if any
  std::optional<std::string> error_;
};

}  // namespace robuter::ctl

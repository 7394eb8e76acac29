// SPDX-License-Identifier: GPL-3.0-or-later
// Splitting a line into its words: one rule for the file loaders, the scripts and the tools.
#pragma once

#include <string_view>
#include <vector>

namespace robuter {

// The words of `line`: the non-empty runs of characters between any of `separators`, as views
// into `line` (none empty; separators at either end or repeated make no empty word).
inline std::vector<std::string_view> split_words(std::string_view line, std::string_view separators) {
  std::vector<std::string_view> out;
  std::size_t start = line.find_first_not_of(separators);
  while (start != std::string_view::npos) {
    std::size_t end = line.find_first_of(separators, start);
    if (end == std::string_view::npos) end = line.size();
    out.push_back(line.substr(start, end - start));
    start = line.find_first_not_of(separators, end);
  }
  return out;
}

}  // namespace robuter

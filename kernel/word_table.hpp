// SPDX-License-Identifier: GPL-3.0-or-later
// Word tables: one list of (word, value) rows both reads a word of a file or an option and names a value in messages.
#pragma once

#include <cstddef>
#include <string_view>

namespace robuter {

// One row of a word table.
template <class T>
struct Word {
  const char* word;  // the word as files, options and messages write it (a string literal)
  T value;           // what it stands for
};

// Sets `out` to the value of the first row whose word is `text`; false (and `out` untouched)
// when no row has it.
template <class T, std::size_t N>
constexpr bool read_word(const Word<T> (&table)[N], std::string_view text, T& out) {
  for (const auto& row : table) {
    if (text == row.word) {
      out = row.value;
      return true;
    }
  }
  return false;
}

// The word of the first row whose value is `value`; "?" when no row has it.
template <class T, std::size_t N>
constexpr const char* word_of(const Word<T> (&table)[N], T value) {
  for (const auto& row : table)
    if (row.value == value) return row.word;
  return "?";
}

}  // namespace robuter

// SPDX-License-Identifier: GPL-3.0-or-later
// Worded enums: one X-macro list makes an enum and its words together; word(e) names a value, from_word<E>(w) reads one back.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

// A list is an X-macro, X(enumerator, "word") once per enumerator in order: the one list makes
// both the enum (`enum class E { LIST(ROBUTER_VOCAB_ENUMERATOR) };`) and its words
// (`ROBUTER_VOCABULARY(E, LIST, fallback)`, in E's namespace), so they hold one entry per
// enumerator, in order, by construction — a value without a word cannot be written.
#define ROBUTER_VOCAB_ENUMERATOR(name, text) name,
#define ROBUTER_VOCAB_WORD(name, text) std::string_view{text},

// The words of `Enum` from its `LIST`, found by argument-dependent lookup (`vocabulary_of`);
// `fallback_word` stands for a value outside the list (only a cast can make one). The words are
// checked at compile time.
#define ROBUTER_VOCABULARY(Enum, LIST, fallback_word)                                                  \
  struct Enum##Vocabulary {                                                                            \
    static constexpr std::array words{LIST(ROBUTER_VOCAB_WORD)};                                       \
    static constexpr std::string_view fallback = fallback_word;                                        \
  };                                                                                                   \
  constexpr Enum##Vocabulary vocabulary_of(Enum) noexcept { return {}; }                               \
  static_assert(::robuter::vocabulary_detail::well_formed(Enum##Vocabulary::words),                    \
                #Enum ": every word non-empty, printable and unique");       \
  static_assert(::robuter::vocabulary_detail::contains(Enum##Vocabulary::words, Enum##Vocabulary::fallback), \
                #Enum ": the fallback is one of the words")

namespace robuter {

namespace vocabulary_detail {
// True when every word is non-empty, printable (a log line's words may hold a blank), and unique.
template <std::size_t N>
constexpr bool well_formed(const std::array<std::string_view, N>& words) {
  for (std::size_t i = 0; i < N; ++i) {
    if (words[i].empty()) return false;
    for (const char c : words[i])
      if (c < ' ' || c >= 0x7F) return false;
    for (std::size_t j = 0; j < i; ++j)
      if (words[i] == words[j]) return false;
  }
  return true;
}
// True when `w` is one of `words`.
template <std::size_t N>
constexpr bool contains(const std::array<std::string_view, N>& words, std::string_view w) {
  for (const std::string_view x : words)
    if (x == w) return true;
  return false;
}
}  // namespace vocabulary_detail

// An enum declared with a vocabulary.
template <class E>
concept Worded = requires { vocabulary_of(E{}); };

// The words of worded enum E (`::words`, `::fallback`).
template <Worded E>
using Vocabulary = decltype(vocabulary_of(E{}));

// How many enumerators E has (its words, one each).
template <Worded E>
inline constexpr std::size_t kEnumerators = Vocabulary<E>::words.size();

// True when every word of E is one token of at most `max_bytes`: no blank, no '*' (a reply's
// words; protocol/codec/vocabulary.hpp asks it of every enum that crosses the link).
template <Worded E>
constexpr bool words_are_tokens(std::size_t max_bytes) noexcept {
  for (const std::string_view w : Vocabulary<E>::words) {
    if (w.size() > max_bytes) return false;
    for (const char c : w)
      if (c == ' ' || c == '*') return false;
  }
  return true;
}

namespace vocabulary_detail {
// Bytes of E's words joined by '|'.
template <Worded E>
constexpr std::size_t joined_size() noexcept {
  std::size_t n = 0;
  for (const std::string_view w : Vocabulary<E>::words) n += w.size() + 1;
  return n - 1;
}
// E's words joined by '|', made once at compile time.
template <Worded E>
inline constexpr std::array<char, joined_size<E>()> kJoined = [] {
  std::array<char, joined_size<E>()> out{};
  std::size_t k = 0;
  for (const std::string_view w : Vocabulary<E>::words) {
    if (k != 0) out[k++] = '|';
    for (const char c : w) out[k++] = c;
  }
  return out;
}();
}  // namespace vocabulary_detail

// E's words joined by '|' ("none|even|odd"): the choices of a configuration key that names an E.
template <Worded E>
constexpr std::string_view word_list() noexcept {
  return {vocabulary_detail::kJoined<E>.data(), vocabulary_detail::kJoined<E>.size()};
}

// The word of `e`: the same in replies, files, options and log lines.
template <Worded E>
constexpr std::string_view word(E e) noexcept {
  const auto i = static_cast<std::size_t>(e);
  return i < kEnumerators<E> ? Vocabulary<E>::words[i] : Vocabulary<E>::fallback;
}

// The enumerator of E whose word is `w`; none when no word matches.
template <Worded E>
constexpr std::optional<E> from_word(std::string_view w) noexcept {
  for (std::size_t i = 0; i < kEnumerators<E>; ++i)
    if (Vocabulary<E>::words[i] == w) return static_cast<E>(i);
  return std::nullopt;
}

}  // namespace robuter

// SPDX-License-Identifier: GPL-3.0-or-later
// Reading text files for the loaders: whole-file read, line splitting, tokens with line numbers.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "modules/planner/lib/result.hpp"

namespace robuter::plan {

inline constexpr std::size_t kMaxTextFileBytes = 64u * 1024u * 1024u;  // largest file a loader reads, bytes

// Why: the loaders parse from memory; this is their only file access. A regular file of at most
// `max_bytes`, or an error with the reason (kernel/input_file.hpp: a folder, a FIFO or /dev/zero
// never hangs or fills memory).
Result<std::string> read_text_file(const std::string& path, std::size_t max_bytes = kMaxTextFileBytes);

// Why: every loader reads its file, then parses the text naming the file: one rule for the file
// access and its error. `parse(text, path)` returns the Result.
template <class Parse>
auto load_text_file(const std::string& path, Parse parse) -> decltype(parse(std::string_view{}, path)) {
  auto text = read_text_file(path);
  if (!text) return text.error();
  return parse(*text, path);
}

// Why: lines without their terminator; a trailing '\r' (CRLF files) is dropped.
std::vector<std::string_view> split_lines(std::string_view text);

// Why: the fields of a line of "key value..." or tab-separated records (spaces and tabs
// separate; none empty), views into `line`.
std::vector<std::string_view> split_words(std::string_view line);

// Why: strict number parsing (the whole token must be a number; no locale).
std::optional<long long> parse_integer(std::string_view s);
std::optional<double> parse_real(std::string_view s);

// Whitespace-separated tokens with the line each starts on, like the thesis' fscanf reading,
// producing errors that name the file and line.
class TokenReader {
 public:
  // One token and where it is.
  struct Token {
    std::string_view text;  // the token's characters
    int line;               // 1-based line number
  };

  TokenReader(std::string_view text, std::string file) : text_(text), file_(std::move(file)) {}

  std::optional<Token> next();
  // Why: the usual "expect a number of this kind here" steps, with clear errors.
  Result<long long> integer(std::string_view what);
  Result<double> real(std::string_view what);
  // Why: a file must end after its last expected item.
  Status expect_end();

  Error error(int line, std::string message) const { return Error{file_, line, std::move(message)}; }
  int line() const { return line_; }

 private:
  // The next token read with `parse`: an error naming `what` and `kind` ("an integer") when it
  // is missing or not one.
  template <class T>
  Result<T> parsed(std::string_view what, std::optional<T> (*parse)(std::string_view), const char* kind);

  std::string_view text_;  // whole file
  std::string file_;       // file name for errors
  std::size_t pos_ = 0;    // next character to read
  int line_ = 1;           // line of pos_
  int last_line_ = 1;      // line of the last token returned (end-of-file errors point here)
};

}  // namespace robuter::plan

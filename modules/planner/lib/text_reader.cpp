// SPDX-License-Identifier: GPL-3.0-or-later
// Whole-file reads, line splitting, strict number parsing and a line-counting tokenizer.
#include "modules/planner/lib/text_reader.hpp"

#include <charconv>
#include <cmath>

#include "kernel/input_file.hpp"
#include "kernel/split_words.hpp"

namespace robuter::plan {

Result<std::string> read_text_file(const std::string& path, std::size_t max_bytes) {
  std::string text;
  if (auto why = read_input_file(path, text, max_bytes)) return Error{path, 0, *why};
  return text;
}

std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    const bool last = end == std::string_view::npos;
    if (last) end = text.size();
    std::string_view line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.push_back(line);
    start = end + 1;
  }
  return lines;
}

std::vector<std::string_view> split_words(std::string_view line) { return robuter::split_words(line, " \t"); }

std::optional<long long> parse_integer(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  long long v = 0;
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || ec != std::errc() || p != s.data() + s.size()) return std::nullopt;
  return v;
}

std::optional<double> parse_real(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  double v = 0.0;
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || ec != std::errc() || p != s.data() + s.size() || !std::isfinite(v))
    return std::nullopt;
  return v;
}

// Why: skips whitespace while counting newlines, then returns the next run of non-space.
std::optional<TokenReader::Token> TokenReader::next() {
  auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; };
  while (pos_ < text_.size() && space(text_[pos_])) {
    if (text_[pos_] == '\n') ++line_;
    ++pos_;
  }
  if (pos_ >= text_.size()) return std::nullopt;
  last_line_ = line_;
  const std::size_t start = pos_;
  while (pos_ < text_.size() && !space(text_[pos_])) ++pos_;
  return Token{text_.substr(start, pos_ - start), line_};
}

template <class T>
Result<T> TokenReader::parsed(std::string_view what, std::optional<T> (*parse)(std::string_view), const char* kind) {
  const auto t = next();
  if (!t) return error(last_line_, "unexpected end of file: expected " + std::string(what));
  const auto v = parse(t->text);
  if (!v)
    return error(t->line, "expected " + std::string(what) + " (" + kind + "), got '" + std::string(t->text) + "'");
  return *v;
}

Result<long long> TokenReader::integer(std::string_view what) { return parsed(what, parse_integer, "an integer"); }

Result<double> TokenReader::real(std::string_view what) { return parsed(what, parse_real, "a number"); }

Status TokenReader::expect_end() {
  const auto t = next();
  if (t) return error(t->line, "unexpected trailing data '" + std::string(t->text) + "'");
  return Ok{};
}

}  // namespace robuter::plan

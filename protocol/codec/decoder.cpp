// SPDX-License-Identifier: GPL-3.0-or-later
// The decoder: looks up the command table and checks parameters against the row's schema.
#include "protocol/codec/decoder.hpp"

#include <cstdint>

namespace robuter::protocol {
namespace {

// The seed's two separators.
constexpr bool is_separator(char c) noexcept { return c == ' ' || c == ','; }

// Walks the parameter text token by token, skipping separator runs.
class Tokens {
 public:
  explicit Tokens(std::string_view text) noexcept : text_(text) {}
  // The next token, or false when only separators remain.
  bool next(std::string_view& token) noexcept {
    while (pos_ < text_.size() && is_separator(text_[pos_])) ++pos_;
    if (pos_ == text_.size()) return false;
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !is_separator(text_[pos_])) ++pos_;
    token = text_.substr(start, pos_ - start);
    return true;
  }

 private:
  std::string_view text_;  // the parameters
  std::size_t pos_ = 0;    // where the next token search starts
};

// Exactly `count` integers (or min_count..count when the row allows optional ones); a wrong
// count wins over a malformed value.
ErrorCode decode_integers(std::string_view params, const Schema& schema, Command& cmd) noexcept {
  Tokens tokens(params);
  std::string_view token;
  std::size_t n = 0;
  ErrorCode first_bad = ErrorCode::none;
  while (tokens.next(token)) {
    if (n >= schema.count) return ErrorCode::bad_parameter_count;
    const ErrorCode e = parse_integer(token, schema.ranges[n], cmd.ints[n]);
    if (e != ErrorCode::none && first_bad == ErrorCode::none) first_bad = e;
    ++n;
  }
  const std::size_t least = schema.min_count > 0 ? schema.min_count : schema.count;
  if (!(n == 0 && schema.or_none) && (n < least || n > schema.count)) return ErrorCode::bad_parameter_count;
  cmd.int_count = static_cast<std::uint8_t>(n);
  return first_bad;
}

// A single token of a single character from the row's set.
ErrorCode decode_one_of(std::string_view params, const Schema& schema, Command& cmd) noexcept {
  Tokens tokens(params);
  std::string_view token;
  if (!tokens.next(token)) return ErrorCode::bad_parameter_count;
  std::string_view extra;
  if (tokens.next(extra)) return ErrorCode::bad_parameter_count;
  if (token.size() != 1 || schema.choices.find(token[0]) == std::string_view::npos) {
    return ErrorCode::bad_parameter;
  }
  cmd.choice = token[0];
  return ErrorCode::none;
}

// A single token of exactly 24 '0'/'1' characters; character k is sensor k+1.
ErrorCode decode_table(std::string_view params, Command& cmd) noexcept {
  Tokens tokens(params);
  std::string_view token;
  if (!tokens.next(token)) return ErrorCode::bad_parameter_count;
  std::string_view extra;
  if (tokens.next(extra)) return ErrorCode::bad_parameter_count;
  if (token.size() != kSensorCount) return ErrorCode::bad_parameter;
  for (std::size_t k = 0; k < kSensorCount; ++k) {
    if (token[k] != '0' && token[k] != '1') return ErrorCode::bad_parameter;
    cmd.table.set(k, token[k] == '1');
  }
  return ErrorCode::none;
}

}  // namespace

// Sign, then at least one digit and nothing else; values beyond int32 are out of range.
ErrorCode parse_integer(std::string_view token, IntRange range, std::int32_t& out) noexcept {
  std::size_t i = 0;
  bool negative = false;
  if (i < token.size() && (token[i] == '+' || token[i] == '-')) {
    negative = token[i] == '-';
    ++i;
  }
  if (i == token.size()) return ErrorCode::not_a_number;
  std::int64_t magnitude = 0;
  bool too_big = false;
  for (; i < token.size(); ++i) {
    const char c = token[i];
    if (c < '0' || c > '9') return ErrorCode::not_a_number;
    if (!too_big) {
      magnitude = magnitude * 10 + (c - '0');
      if (magnitude > (std::int64_t{1} << 32)) too_big = true;
    }
  }
  if (too_big) return ErrorCode::out_of_range;
  const std::int64_t value = negative ? -magnitude : magnitude;
  if (value < range.min || value > range.max) return ErrorCode::out_of_range;
  out = static_cast<std::int32_t>(value);
  return ErrorCode::none;
}

// Table lookup first (so `Zz 1 2` is unknown, not a parameter error), then the schema.
Decoded decode(std::string_view line) noexcept {
  Decoded d;
  if (line.size() < 2) {
    d.error = ErrorCode::line_too_short;
    return d;
  }
  const CommandRow* row = find_command(line[0], line[1]);
  if (row == nullptr) {
    d.error = ErrorCode::unknown_command;
    return d;
  }
  const std::string_view params = line.substr(2);
  Command& cmd = d.command;
  cmd.id = row->id;
  switch (row->schema.kind) {
    case SchemaKind::none: {
      Tokens tokens(params);
      std::string_view token;
      if (tokens.next(token)) d.error = ErrorCode::bad_parameter_count;
      break;
    }
    case SchemaKind::integers: d.error = decode_integers(params, row->schema, cmd); break;
    case SchemaKind::one_of: d.error = decode_one_of(params, row->schema, cmd); break;
    case SchemaKind::table: d.error = decode_table(params, cmd); break;
    case SchemaKind::text:
      if (params.empty()) d.error = ErrorCode::bad_parameter_count;
      cmd.text = params;
      break;
  }
  if (d.error == ErrorCode::none) d.row = row;
  return d;
}

}  // namespace robuter::protocol

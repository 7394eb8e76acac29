// SPDX-License-Identifier: GPL-3.0-or-later
// Tests of the framing: terminators, length bound, bad bytes, stop byte, split input.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "protocol/codec/line_assembler.hpp"

namespace robuter::protocol {
namespace {

// What one event looked like, copied out of the assembler's buffer.
struct Seen {
  FrameEvent::Kind kind;
  std::string line;
  ErrorCode error;
};

// Feeds `bytes` in one piece and records every event.
std::vector<Seen> run(LineAssembler& a, std::string_view bytes) {
  std::vector<Seen> seen;
  a.feed(std::span(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()),
         [&](const FrameEvent& e) { seen.push_back({e.kind, std::string(e.line), e.error}); });
  return seen;
}

using K = FrameEvent::Kind;

TEST(LineAssembler, CrEndsALine) {
  LineAssembler a;
  const auto s = run(a, "BC\r");
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].kind, K::line);
  EXPECT_EQ(s[0].line, "BC");
}

TEST(LineAssembler, BareLfEndsALine) {
  LineAssembler a;
  const auto s = run(a, "BC\nBO\n");
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].line, "BC");
  EXPECT_EQ(s[1].line, "BO");
}

TEST(LineAssembler, CrLfIsOneTerminator) {
  LineAssembler a;
  const auto s = run(a, "BC\r\nBO\r\n");
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].line, "BC");
  EXPECT_EQ(s[1].line, "BO");
}

TEST(LineAssembler, CrLfSplitAcrossFeeds) {
  LineAssembler a;
  EXPECT_EQ(run(a, "BC\r").size(), 1u);
  const auto s = run(a, "\nBO\r");
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].line, "BO");
}

TEST(LineAssembler, LfLfGivesAnEmptyLine) {
  LineAssembler a;
  const auto s = run(a, "BC\r\n\n");
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[1].kind, K::line);
  EXPECT_EQ(s[1].line, "");
}

TEST(LineAssembler, CrCrGivesAnEmptyLine) {
  LineAssembler a;
  const auto s = run(a, "\r\r");
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].line, "");
  EXPECT_EQ(s[1].line, "");
}

TEST(LineAssembler, ExactlyMaxLengthIsAccepted) {
  LineAssembler a;
  const std::string line(LineAssembler::MAX_LENGTH, 'a');
  const auto s = run(a, line + "\r");
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].kind, K::line);
  EXPECT_EQ(s[0].line.size(), LineAssembler::MAX_LENGTH);
}

TEST(LineAssembler, OneByteTooLongIsOneError) {
  LineAssembler a;
  const std::string line(LineAssembler::MAX_LENGTH + 1, 'a');
  const auto s = run(a, line + "\rBC\r");
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].kind, K::error);
  EXPECT_EQ(s[0].error, ErrorCode::line_too_long);
  EXPECT_EQ(s[1].line, "BC");
}

TEST(LineAssembler, LongLineInPiecesIsOneError) {
  LineAssembler a;
  std::vector<Seen> all;
  for (int i = 0; i < 100; ++i) {
    for (auto& e : run(a, std::string(100, 'x'))) all.push_back(e);
  }
  for (auto& e : run(a, "\r\nBO\r")) all.push_back(e);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0].error, ErrorCode::line_too_long);
  EXPECT_EQ(all[1].line, "BO");
}

TEST(LineAssembler, NulMakesTheLineBad) {
  LineAssembler a;
  const auto s = run(a, std::string("B\0C\rBC\r", 7));
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].kind, K::error);
  EXPECT_EQ(s[0].error, ErrorCode::bad_byte);
  EXPECT_EQ(s[1].line, "BC");
}

TEST(LineAssembler, FfAndControlsMakeTheLineBad) {
  LineAssembler a;
  for (const char bad : {'\xFF', '\x01', '\t', '\x7F', '\x80', '\x1B'}) {
    std::string line = "AM 1";
    line += bad;
    line += "0 10\r";
    const auto s = run(a, line);
    ASSERT_EQ(s.size(), 1u);
    EXPECT_EQ(s[0].error, ErrorCode::bad_byte) << static_cast<int>(bad);
  }
}

TEST(LineAssembler, StopByteIsReportedAtOnceAndNotInTheLine) {
  LineAssembler a;
  const auto s = run(a, "\x18" "BC\r");
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].kind, K::stop);
  EXPECT_EQ(s[1].kind, K::line);
  EXPECT_EQ(s[1].line, "BC");
}

TEST(LineAssembler, StopByteCancelsThePartialLine) {
  LineAssembler a;
  const auto s = run(a, "AM 1\x18" "0 10\rBO\r");
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[0].kind, K::stop);
  EXPECT_EQ(s[1].kind, K::error);
  EXPECT_EQ(s[1].error, ErrorCode::stopped);
  EXPECT_EQ(s[2].line, "BO");
}

TEST(LineAssembler, StopByteBetweenCrAndLfKeepsThePair) {
  LineAssembler a;
  const auto s = run(a, "BC\r\x18\nBO\r");
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[0].line, "BC");
  EXPECT_EQ(s[1].kind, K::stop);
  EXPECT_EQ(s[2].line, "BO");
}

TEST(LineAssembler, ByteAtATimeMatchesOneFeed) {
  LineAssembler whole, piecewise;
  const std::string input = "BC\r\nAM 5,4\nUT1011\r\x18" "BO\r";
  const auto expected = run(whole, input);
  std::vector<Seen> got;
  for (char c : input) {
    for (auto& e : run(piecewise, std::string(1, c))) got.push_back(e);
  }
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i].kind, expected[i].kind);
    EXPECT_EQ(got[i].line, expected[i].line);
  }
}

TEST(LineAssembler, ResetDropsThePartialLine) {
  LineAssembler a;
  run(a, "AM 10");
  EXPECT_EQ(a.pending(), 5u);
  a.reset();
  const auto s = run(a, "BC\r");
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].line, "BC");
}

}  // namespace
}  // namespace robuter::protocol

// SPDX-License-Identifier: GPL-3.0-or-later
// The reply writer alone: one line per reply, overflow safety, session snapshot.
#include <gtest/gtest.h>

#include <string>

#include "protocol/codec/reply_writer.hpp"

namespace robuter::protocol {
namespace {

TEST(ReplyWriter, NothingWrittenIsAnInternalError) {
  SessionState s;
  s.verbose_errors = true;
  ReplyWriter w(s);
  w.begin();
  EXPECT_EQ(w.finish(), "error 15 internal\r");
}

TEST(ReplyWriter, LaterChoiceReplacesEarlier) {
  SessionState s;
  ReplyWriter w(s);
  w.begin();
  w.open("S");
  w.field(1);
  w.ack();
  EXPECT_EQ(w.finish(), "ack\r");
  w.begin();
  w.ack();
  w.error(ErrorCode::busy);
  EXPECT_EQ(w.finish(), "error\r");
}

TEST(ReplyWriter, OverflowBecomesInternalError) {
  SessionState s;
  ReplyWriter w(s);
  w.begin();
  w.open("P");
  for (int i = 0; i < 200; ++i) w.field(-2147483647);
  EXPECT_EQ(w.finish(), "error\r");
}

TEST(ReplyWriter, WordsAreCutAndCleaned) {
  SessionState s;
  ReplyWriter w(s);
  w.begin();
  w.open("K");
  w.word(std::string(100, 'n'));
  w.word("x\ty");
  EXPECT_EQ(w.finish(), "K " + std::string(kMaxTokenLength, 'n') + " x_y\r");
}

TEST(ReplyWriter, FinishTwiceGivesTheSameLine) {
  SessionState s;
  s.checksums = true;
  ReplyWriter w(s);
  w.begin();
  w.ack();
  const std::string first(w.finish());
  w.field(5);
  EXPECT_EQ(w.finish(), first);
  EXPECT_EQ(first, "ack*E373\r");
}

TEST(ReplyWriter, ModeIsFrozenAtBegin) {
  SessionState s;
  ReplyWriter w(s);
  w.begin();
  s.terminator = Terminator::crlf;
  w.ack();
  EXPECT_EQ(w.finish(), "ack\r");
  w.begin();
  w.ack();
  EXPECT_EQ(w.finish(), "ack\r\n");
}

}  // namespace
}  // namespace robuter::protocol

// SPDX-License-Identifier: GPL-3.0-or-later
// Reply lines of the PTU protocol: assembly from bytes and parsing of terse, verbose and echoed forms.
#include <gtest/gtest.h>

#include <string>

#include "modules/ptu/ptu_replies.hpp"

namespace robuter::ptu {
namespace {

std::string feed(ReplyAssembler& a, const std::string& bytes, bool* bad = nullptr) {
  std::string last;
  for (char c : bytes)
    if (a.push(static_cast<std::uint8_t>(c))) {
      last = std::string(a.line());
      if (bad) *bad = a.bad();
    }
  return last;
}

TEST(PtuReplies, LinesEndAtCrOrLfAndSkipBlanks) {
  ReplyAssembler a;
  EXPECT_EQ(feed(a, "* 12\r\n"), "* 12");
  EXPECT_EQ(feed(a, "\r\n\r\n"), "");
  EXPECT_EQ(feed(a, "ED *\r"), "ED *");
  bool bad = false;
  EXPECT_EQ(feed(a, std::string(100, 'x') + "\r", &bad).size(), ReplyAssembler::kCapacity);
  EXPECT_TRUE(bad);
  EXPECT_EQ(feed(a, std::string("*\x01\r"), &bad), "*\x01");
  EXPECT_TRUE(bad);
  EXPECT_EQ(feed(a, "* 3\r", &bad), "* 3");
  EXPECT_FALSE(bad);
}

TEST(PtuReplies, ParseForms) {
  EXPECT_EQ(parse_reply("*").kind, ReplyKind::ok);
  EXPECT_FALSE(parse_reply("*").number);
  EXPECT_EQ(*parse_reply("* -1755").number, -1755);
  EXPECT_EQ(*parse_reply("* Current Pan position is 1655").number, 1655);
  EXPECT_EQ(*parse_reply("PP * 12").number, 12);  // echo on
  EXPECT_EQ(*parse_reply("* Target Pan speed is 1500 positions/sec").number, 1500);
  EXPECT_EQ(parse_reply("! Illegal Command").kind, ReplyKind::refused);
  EXPECT_EQ(parse_reply("hello").kind, ReplyKind::garbage);
  EXPECT_EQ(parse_reply("* 99999999999").kind, ReplyKind::garbage);
}

TEST(PtuReplies, FormatCommands) {
  char buf[16];
  EXPECT_EQ(std::string(buf, format_command(buf, sizeof buf, "PP")), "PP\r");
  EXPECT_EQ(std::string(buf, format_command(buf, sizeof buf, "pp", -1755)), "pp-1755\r");
  EXPECT_EQ(std::string(buf, format_command(buf, sizeof buf, "PA", 6000)), "PA6000\r");
  EXPECT_EQ(format_command(buf, 4, "pp", -1755), 0u);
}

}  // namespace
}  // namespace robuter::ptu

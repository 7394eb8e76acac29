// SPDX-License-Identifier: GPL-3.0-or-later
// robuterctl's pairing of replies by the protocol, and its decoding, without a robot.
#include <gtest/gtest.h>

#include "tools/robuterctl/commands.hpp"
#include "tools/robuterctl/decode.hpp"
#include "tools/robuterctl/pairing.hpp"

namespace robuter::ctl {
namespace {

using Kind = Incoming::Kind;

TEST(Pairing, StaleReplyAnswersNothing) {
  Pairing p;
  p.outgoing("BO");
  EXPECT_EQ(p.incoming("C 444").kind, Kind::unexpected);  // left by an earlier client
  const Incoming in = p.incoming("S 0 0 0 0 101");
  EXPECT_EQ(in.kind, Kind::reply);
  EXPECT_EQ(in.command, "BO");
  EXPECT_TRUE(p.waiting().empty());
}

TEST(Pairing, StreamLinesAreNeverReplies) {
  Pairing p;
  p.outgoing("BO");
  EXPECT_EQ(p.incoming("@ 16748 0 0 1 0 0 0 1603").kind, Kind::stream);
  EXPECT_EQ(p.incoming("S 16748 0 0 1 1603").kind, Kind::reply);
}

TEST(Pairing, ChecksumsFollowXC) {
  Pairing p;
  EXPECT_EQ(p.outgoing("XC1"), "XC1\r");
  EXPECT_EQ(p.incoming("ack").kind, Kind::reply);
  ASSERT_TRUE(p.checksums());
  EXPECT_EQ(p.outgoing("BC"), "BC*0E06\r");  // docs/PROTOCOL.md §9
  const Incoming c = p.incoming("C 1523*B39B");
  EXPECT_EQ(c.kind, Kind::reply);
  EXPECT_EQ(c.text, "C 1523");
  EXPECT_FALSE(c.checksum_bad);
  p.outgoing("BC");
  EXPECT_TRUE(p.incoming("C 1523*0000").checksum_bad);
  EXPECT_EQ(p.outgoing("XC0"), "XC0*553F\r");
  EXPECT_EQ(p.incoming("ack*E373").kind, Kind::reply);
  EXPECT_FALSE(p.checksums());
}

TEST(Pairing, ALineWithoutReplyIsPassedOver) {
  Pairing p;
  p.outgoing("BC");  // dropped unexecuted by robuterd: no reply
  p.outgoing("BO");
  const Incoming in = p.incoming("S 1 2 3 0 9");
  EXPECT_EQ(in.command, "BO");
  EXPECT_EQ(in.lost, 1u);
}

TEST(Pairing, RepliesFitTheirCommands) {
  EXPECT_TRUE(reply_fits("AM 10 10", "ack"));
  EXPECT_FALSE(reply_fits("BO", "ack"));
  EXPECT_TRUE(reply_fits("Zz", "error"));
  EXPECT_TRUE(reply_fits("XV", "V robuterd 0.1.0 proto 1 caps stop"));
  EXPECT_FALSE(reply_fits("BV", "V robuterd 0.1.0 proto 1 caps stop"));
  EXPECT_TRUE(reply_fits("XD", "D off none off none off none 0 0 0 off none none 0 6106"));
  EXPECT_TRUE(reply_fits("XE", "E 0 1 stop-byte 7 359 0 seed 0"));
}

TEST(Decode, ExtensionsDecodedOnce) {
  EXPECT_NE(describe_reply("XK", "K 6000 180 42 1 serial 3000 0 0 12 40 6001").find("serial"), std::string::npos);
  EXPECT_NE(describe_reply("XP", "P moving 150000 55000 13950 1480 3 4 812 4650 1523").find("planner moving"), std::string::npos);
  EXPECT_NE(describe_reply("XM", "M 3 2 50 0 0 .#.| P ").find("|.#.|"), std::string::npos);
  EXPECT_EQ(describe_reply("AM 1 1", "ack"), "");  // nothing to add: printed once
  const EmergencyView v = read_xe("E 0 1 obstacle 7 18234 0 seed 0");
  EXPECT_TRUE(v.latched);
  EXPECT_EQ(v.cause, "obstacle");
  EXPECT_TRUE(read_stream("@ 1 2 3 0 0 0 2 99").latched);
  EXPECT_TRUE(read_xe("E 0 0 none 7 18234 0 envelope 1").protective);
  EXPECT_FALSE(read_xe("E 0 0 none 7 18234 100 envelope 0").protective);
  EXPECT_TRUE(read_stream("@ 1 2 3 1 0 0 4 99").protective);
  EXPECT_NE(describe_stream("@ 1 2 3 1 0 0 4 99").find("protective stop"), std::string::npos);
}

TEST(Help, EveryCommandAndExtension) {
  for (const char* c : {"XD", "XG", "XH", "XP", "XM", "XL0", "XL1", "XL2", "XK", "XV", "XS", "XT1"}) {
    bool found = false;
    for (const auto& e : command_table()) found |= e.name == c;
    EXPECT_TRUE(found) << c;
  }
  EXPECT_NE(help_text("AM").find("AM <left> <right>"), std::string::npos);
  EXPECT_NE(help_text("nothing").find("no command"), std::string::npos);
}

}  // namespace
}  // namespace robuter::ctl

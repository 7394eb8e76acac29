// SPDX-License-Identifier: GPL-3.0-or-later
// The codec on a link: framing errors, terminators, stop byte, pipelining, random bytes.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "tests/protocol/codec_harness.hpp"

namespace robuter::protocol::testing {
namespace {

TEST(Link, TenKilobyteLineIsOneErrorThenInSync) {
  Harness h;
  const auto r = h.feed(std::string(10 * 1024, 'A') + "\rBC\r");
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0], "error\r");
  EXPECT_EQ(r[1], "C 1523\r");
}

TEST(Link, TenKilobyteLineWithoutTerminatorYetGivesNothing) {
  Harness h;
  EXPECT_TRUE(h.feed(std::string(10 * 1024, '1')).empty());
  EXPECT_EQ(h.feed("\n"), std::vector<std::string>{"error\r"});
  EXPECT_EQ(h.ask("BT"), "T 33");
}

TEST(Link, NulAndFfLinesAreOneErrorEach) {
  Harness h;
  static constexpr char kBytes[] = "AM 1\0 1\rA\xFFM 1 1\rBC\r";
  const auto r = h.feed(std::string(kBytes, sizeof kBytes - 1));
  ASSERT_EQ(r.size(), 3u);
  EXPECT_EQ(r[0], "error\r");
  EXPECT_EQ(r[1], "error\r");
  EXPECT_EQ(r[2], "C 1523\r");
  EXPECT_EQ(h.port.motion_requests, 0);
}

TEST(Link, BareLfAndCrLfClients) {
  Harness h;
  EXPECT_EQ(h.feed("BC\n"), std::vector<std::string>{"C 1523\r"});
  EXPECT_EQ(h.feed("BC\r\n"), std::vector<std::string>{"C 1523\r"});
  EXPECT_EQ(h.feed("BC\r\nBT\r\n"), (std::vector<std::string>{"C 1523\r", "T 33\r"}));
}

TEST(Link, EmptyAndOneCharLinesAreErrors) {
  Harness h;
  EXPECT_EQ(h.feed("\r"), std::vector<std::string>{"error\r"});
  EXPECT_EQ(h.feed("B\r"), std::vector<std::string>{"error\r"});
}

TEST(Link, StopByteStopsAtOnceWithoutAReply) {
  Harness h;
  EXPECT_TRUE(h.feed("\x18").empty());
  EXPECT_EQ(h.port.stops, 1);
  EXPECT_EQ(h.ask("BC"), "C 1523");
}

TEST(Link, StopByteCancelsTheLineItInterrupts) {
  Harness h;
  h.codec.session().verbose_errors = true;
  const auto r = h.feed("AM 1\x18" "0 10\r");
  EXPECT_EQ(h.port.stops, 1);
  EXPECT_EQ(h.port.motion_requests, 0);
  EXPECT_EQ(r, std::vector<std::string>{"error 14 stopped\r"});
}

TEST(Link, PipelinedThousandLinesGiveThousandRepliesInOrder) {
  Harness h;
  std::string bytes;
  for (int i = 0; i < 1000; ++i) {
    switch (i % 4) {
      case 0: bytes += "BC\r"; break;
      case 1: bytes += "AM " + std::to_string(i % 100) + " 1\r"; break;
      case 2: bytes += "Zz\r"; break;
      default: bytes += "UN\r"; break;
    }
  }
  const auto r = h.feed(bytes);
  ASSERT_EQ(r.size(), 1000u);
  for (int i = 0; i < 1000; ++i) {
    const char* expected[] = {"C 1523\r", "ack\r", "error\r", "N 3\r"};
    ASSERT_EQ(r[static_cast<std::size_t>(i)], expected[i % 4]) << i;
  }
  EXPECT_EQ(h.port.motion_requests, 250);
}

TEST(Link, MegabyteOfRandomBytesNeverCrashesAndResyncs) {
  Harness h;
  std::mt19937 rng(20240601);
  std::string noise(1 << 20, '\0');
  for (char& c : noise) c = static_cast<char>(rng() & 0xFF);
  std::size_t replies = 0;
  for (std::size_t off = 0; off < noise.size(); off += 4096) {
    replies += h.feed(std::string_view(noise).substr(off, 4096)).size();
  }
  // Noise may have switched session options (XB1, XC1, XL1...): reset the session only.
  h.codec.session() = SessionState{};
  const auto r = h.feed("\rBC\r");
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[1], "C 1523\r");
  for (const std::string& reply : h.replies) {
    ASSERT_FALSE(reply.empty());
    const std::string_view body = std::string_view(reply).substr(0, reply.find_first_of("\r\n"));
    for (char c : body) ASSERT_TRUE(c >= 0x20 && c < 0x7F);
  }
  EXPECT_GT(replies, 0u);
}

TEST(Link, EveryReplyIsOneLine) {
  Harness h;
  h.port.processes[0].name = "bad name\r\nwith breaks";
  for (const char* line : {"BO", "BU", "BV", "BC", "BT", "BP", "BF", "BD", "UN", "USN", "USS",
                           "XE", "XK", "XV"}) {
    const std::string r = h.ask(line);
    EXPECT_EQ(r.find('\r'), std::string::npos) << line;
    EXPECT_EQ(r.find('\n'), std::string::npos) << line;
  }
}

}  // namespace
}  // namespace robuter::protocol::testing

// SPDX-License-Identifier: GPL-3.0-or-later
// Command-link sessions and the stop byte's guarantee (issue #14): the whole firmware on a pty.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <string>

#include "kernel/log.hpp"

#include "modules/firmware/sim_firmware.hpp"
#include "tests/support/log_capture.hpp"

namespace robuter {
namespace {

// Starts a turn on the spot and waits until the drive has it (the gate holds until the ring
// has read the watch-dog sensors).
void start_turning(test::SimFirmware& fw) {
  ASSERT_EQ(fw.ask("ASN"), "ack");
  ASSERT_EQ(fw.ask("AM 20 -20"), "ack");
  ASSERT_TRUE(fw.run_until([&] { return fw.wheels() == std::pair{20, -20}; }, 300));
}

// The client reads everything robuterd queued (the pty takes it a few kB at a time).
void drain(test::SimFirmware& fw) {
  for (int quiet = 0, i = 0; quiet < 5 && i < 2000; ++i) {
    const auto [replies, stream] = fw.count_lines();
    quiet = replies + stream == 0 ? quiet + 1 : 0;
    fw.step();
  }
}

std::string cause(const std::string& xe) {
  char word[32] = {};
  int held = 0, latched = 0;
  return std::sscanf(xe.c_str(), "E %d %d %31s", &held, &latched, word) == 3 ? word : "";
}

// A client that writes XM lines without reading fills the 64 kB output ring (and the pty's own
// buffer); a stop byte after that still reaches the drive in the activation that reads it.
TEST(LinkSessions, StopByteActsBehindSixtyFourKilobytesOfUnreadReplies) {
  test::SimFirmware fw;
  ASSERT_TRUE(fw.ok()) << fw.error();
  fw.run_ticks(100);
  start_turning(fw);
  for (int i = 0; i < 100; ++i) fw.send_raw("XM\r");  // 100 × 1.7 kB of replies, none read
  fw.run_ticks(3);
  EXPECT_GT(fw.bb().link_status.reader().peek().lines_discarded, 0u);
  EXPECT_EQ(fw.wheels(), (std::pair{20, -20}));  // dropping replies stops nothing by itself
  const std::uint64_t tick = fw.kernel().tick();
  fw.send_raw("\r\x18");
  fw.step();  // one tick: the byte is read by an event activation before it
  EXPECT_EQ(fw.wheels(), (std::pair{0, 0})) << "stop byte not acted on within one tick";
  EXPECT_EQ(fw.kernel().tick(), tick + 1);
  EXPECT_FALSE(fw.sim().drive().servo());
  drain(fw);  // the client reads what was queued
  const auto xe = fw.ask("XE");
  ASSERT_TRUE(xe);
  EXPECT_EQ(cause(*xe), "stop-byte") << *xe;
}

// A line whose reply cannot be queued is never executed (later, unseen): AM with the ring full
// moves nothing, and the link answers again once the client reads.
TEST(LinkSessions, LineWhoseReplyCannotBeQueuedIsDroppedUnexecuted) {
  test::SimFirmware fw;
  ASSERT_TRUE(fw.ok()) << fw.error();
  fw.run_ticks(100);
  ASSERT_EQ(fw.ask("ASN"), "ack");
  for (int i = 0; i < 100; ++i) fw.send_raw("XM\r");
  fw.run_ticks(3);
  const std::uint64_t dropped = fw.bb().link_status.reader().peek().lines_discarded;
  ASSERT_GT(dropped, 0u);
  // The pty takes a few kB more now and then; 20 more XM in the same write use that up.
  std::string lines;
  for (int i = 0; i < 20; ++i) lines += "XM\r";
  fw.send_raw(lines + "AM 20 20\r");
  fw.run_ticks(100);
  EXPECT_EQ(fw.wheels(), (std::pair{0, 0}));
  EXPECT_GT(fw.bb().link_status.reader().peek().lines_discarded, dropped);
  drain(fw);
  EXPECT_EQ(fw.ask("BC").value_or("").substr(0, 2), "C ");
  fw.run_ticks(100);
  EXPECT_EQ(fw.wheels(), (std::pair{0, 0}));  // the dropped AM never runs later
}

// `printf 'ASN\rAM 20 -20\r' > pty` after an earlier client left, and `printf '\x18' > pty`:
// both are served although the client opened, wrote and closed between two activations.
TEST(LinkSessions, OneShotClientsAreServedAfterAnEarlierClientLeft) {
  test::SimFirmware fw;
  ASSERT_TRUE(fw.ok()) << fw.error();
  fw.run_ticks(100);
  EXPECT_EQ(fw.ask("BO").value_or("").substr(0, 2), "S ");
  fw.close_client();
  fw.run_ticks(5);
  ASSERT_TRUE(fw.one_shot("ASN\rAM 20 -20\r"));
  EXPECT_TRUE(fw.run_until([&] { return fw.wheels() == std::pair{20, -20}; }, 300)) << "one-shot motion not served";
  fw.run_ticks(20);
  ASSERT_TRUE(fw.one_shot("\x18"));
  fw.step();
  EXPECT_EQ(fw.wheels(), (std::pair{0, 0})) << "one-shot stop byte not served";
  fw.run_ticks(100);  // at rest: XR is accepted only once the robot has stopped
  ASSERT_TRUE(fw.one_shot("XR\r"));  // alone: a request in the same read would be judged before it
  fw.run_ticks(3);
  ASSERT_TRUE(fw.one_shot("ASN\rAM 10 -10\r"));
  EXPECT_TRUE(fw.run_until([&] { return fw.wheels() == std::pair{10, -10}; }, 300));
  ASSERT_TRUE(fw.one_shot("AM 0 0\r"));
  EXPECT_TRUE(fw.run_until([&] { return fw.wheels() == std::pair{0, 0}; }, 20)) << "one-shot AM 0 0 not served";
}

// Settings, half lines and unread replies of one client never reach the next one.
TEST(LinkSessions, EveryNewClientStartsAFreshSession) {
  test::SimFirmware fw;
  ASSERT_TRUE(fw.ok()) << fw.error();
  fw.run_ticks(10);
  EXPECT_EQ(fw.ask("XB1"), "ack");
  EXPECT_EQ(fw.ask("Zz"), "error 1 unknown-command");
  EXPECT_EQ(fw.ask("XL1"), "ack");
  fw.send_raw("BO\r");  // a reply never read
  fw.run_ticks(3);
  fw.send_raw("AM 10");  // a half line
  fw.run_ticks(3);
  ASSERT_TRUE(fw.reconnect());
  fw.run_ticks(3);
  EXPECT_EQ(fw.ask("Zz"), "error");  // seed behaviour again: bare error, CR, no stale reply
  EXPECT_EQ(fw.ask("BC").value_or("").substr(0, 2), "C ");
  // One-shot clients in a row: XB1 from the first does not change the second's errors.
  fw.close_client();
  fw.run_ticks(3);
  ASSERT_TRUE(fw.one_shot("XB1\r"));
  fw.run_ticks(3);
  ASSERT_TRUE(fw.reconnect());
  fw.run_ticks(3);
  EXPECT_EQ(fw.ask("Zz"), "error");
  EXPECT_EQ(fw.bb().link_status.reader().peek().sessions, 4u);
}


// A second program opening the client's pty (a terminal beside a script; a stale path of another
// program's pointing at a reused /dev/pts/N) neither ends nor restarts the session, and is said
// in the log: from then on both read the replies.
TEST(LinkSessions, ASecondProgramOnTheLinkIsLoggedAndLeavesTheSessionAsItIs) {
  test::SimFirmware fw;
  ASSERT_TRUE(fw.ok()) << fw.error();
  fw.run_ticks(10);
  EXPECT_EQ(fw.ask("XB1"), "ack");
  test::log_since_last();
  const int other = ::open(fw.pty_path().c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK);
  ASSERT_GE(other, 0);
  fw.run_ticks(3);
  const std::string said = test::log_since_last();
  EXPECT_NE(said.find("a second program opened"), std::string::npos) << said;
  ::close(other);
  fw.run_ticks(3);
  EXPECT_EQ(fw.ask("Zz"), "error 1 unknown-command");  // XB1 still in force: the same session
  EXPECT_EQ(fw.bb().link_status.reader().peek().sessions, 1u);
}

// [links] stop_when_clients_leave: the last client's close stops the robot like a stop byte.
// Off (the default), the robot keeps its motion and one-shot commands work.
TEST(LinkSessions, StopWhenClientsLeaveIsAnOption) {
  for (const bool stop : {false, true}) {
    Config cfg;
    cfg.links.stop_when_clients_leave = stop;
    test::SimFirmware fw("", cfg);
    ASSERT_TRUE(fw.ok()) << fw.error();
    fw.run_ticks(100);
    start_turning(fw);
    fw.close_client();
    fw.run_ticks(3);
    EXPECT_EQ(fw.wheels(), (stop ? std::pair{0, 0} : std::pair{20, -20})) << "stop_when_clients_leave " << stop;
    ASSERT_TRUE(fw.reconnect());
    const auto xe = fw.ask("XE");
    ASSERT_TRUE(xe);
    EXPECT_EQ(cause(*xe), stop ? "stop-byte" : "none") << *xe;
  }
}

}  // namespace
}  // namespace robuter

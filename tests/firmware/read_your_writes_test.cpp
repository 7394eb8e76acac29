// SPDX-License-Identifier: GPL-3.0-or-later
// Read-your-writes (issue #14, item 2): after an `ack`, every later query already reflects the
// command — the whole firmware on a pty, simulated ticks, lines pipelined in one write.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "modules/firmware/sim_firmware.hpp"

namespace robuter {
namespace {

using Replies = std::vector<std::string>;

// BO's servo field ("S x y theta servo clock"), -1 when the reply is not a posture.
int servo_of(const std::string& bo) {
  int x = 0, y = 0, t = 0, servo = -1;
  unsigned long clock = 0;
  return std::sscanf(bo.c_str(), "S %d %d %d %d %lu", &x, &y, &t, &servo, &clock) == 5 ? servo : -1;
}

// BO without its clock ("S x y theta servo").
std::string posture_of(const std::string& bo) {
  const auto last = bo.rfind(' ');
  return last == std::string::npos ? bo : bo.substr(0, last);
}

// XE without its enabled mask and clock ("E held latched cause").
std::string emergency_of(const std::string& xe) {
  char cause[32] = {};
  int held = 0, latched = 0;
  if (std::sscanf(xe.c_str(), "E %d %d %31s", &held, &latched, cause) != 3) return xe;
  return "E " + std::to_string(held) + " " + std::to_string(latched) + " " + cause;
}

class ReadYourWrites : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(fw.ok()) << fw.error();
    fw.run_ticks(20);
  }
  test::SimFirmware fw;
};

// `ASN` then `BO`, in one write and one line at a time: BO reads servo 1; ASF, servo 0.
TEST_F(ReadYourWrites, ServoCommandIsSeenByTheNextBO) {
  const Replies r = fw.exchange("ASN\rBO\rASF\rBO\r", 4);
  ASSERT_EQ(r.size(), 4u);
  EXPECT_EQ(r[0], "ack");
  EXPECT_EQ(servo_of(r[1]), 1) << r[1];
  EXPECT_EQ(r[2], "ack");
  EXPECT_EQ(servo_of(r[3]), 0) << r[3];
  ASSERT_EQ(fw.ask("ASN"), "ack");
  EXPECT_EQ(servo_of(fw.ask("BO").value_or("")), 1);
}

// `AC 1000 -2000 4500` then `BO`: the new posture, not the old one.
TEST_F(ReadYourWrites, OdometrySetIsSeenByTheNextBO) {
  const Replies r = fw.exchange("AC 1000 -2000 4500\rBO\rAC -7 8 -9000\rBO\r", 4);
  ASSERT_EQ(r.size(), 4u);
  EXPECT_EQ(r[0], "ack");
  EXPECT_EQ(posture_of(r[1]), "S 1000 -2000 4500 0");
  EXPECT_EQ(r[2], "ack");
  EXPECT_EQ(posture_of(r[3]), "S -7 8 -9000 0");
  ASSERT_EQ(fw.ask("AC 5 6 7"), "ack");
  EXPECT_EQ(posture_of(fw.ask("BO").value_or("")), "S 5 6 7 0");
}

// A line after a stop byte in the same read sees the latch the byte made; XR acknowledged means
// the next XE says none.
TEST_F(ReadYourWrites, LineAfterAStopByteSeesTheLatchAndXrClearsIt) {
  Replies r = fw.exchange("\x18XE\rBO\r", 2);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(emergency_of(r[0]), "E 0 1 stop-byte");
  EXPECT_EQ(servo_of(r[1]), 0);
  r = fw.exchange("XR\rXE\r", 2);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0], "ack");
  EXPECT_EQ(emergency_of(r[1]), "E 0 0 none");
  // XR right behind the stop byte judges the latch that byte made (and clears it: at rest).
  r = fw.exchange("\x18XR\rXE\rASN\rBO\r", 4);
  ASSERT_EQ(r.size(), 4u);
  EXPECT_EQ(r[0], "ack");
  EXPECT_EQ(emergency_of(r[1]), "E 0 0 none");
  EXPECT_EQ(r[2], "ack");
  EXPECT_EQ(servo_of(r[3]), 1);
  // One line at a time, too.
  fw.send_raw("\x18");
  EXPECT_EQ(emergency_of(fw.ask("XE").value_or("")), "E 0 1 stop-byte");
  ASSERT_EQ(fw.ask("XR"), "ack");
  EXPECT_EQ(emergency_of(fw.ask("XE").value_or("")), "E 0 0 none");
}

// After a communication-loss trip, the first XR is judged on the link that carries it (alive
// again), not refused until the emergency module's next period.
TEST(ReadYourWritesCommLoss, FirstXrAfterACommunicationLossIsAccepted) {
  Config cfg;
  cfg.emergency.comm_limit_ticks = 50;
  test::SimFirmware fw("", cfg);
  ASSERT_TRUE(fw.ok()) << fw.error();
  fw.run_ticks(20);
  ASSERT_EQ(fw.ask("ASN"), "ack");  // a powered servo: the silence interrupts something
  fw.run_ticks(150);
  const EmergencyState& e = fw.bb().emergency.reader().peek();
  ASSERT_TRUE(e.latched);
  ASSERT_EQ(e.cause, EmergencyCause::comm_loss);
  const Replies r = fw.exchange("XR\rXE\r", 2);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0], "ack");
  EXPECT_EQ(emergency_of(r[1]), "E 0 0 none");
}

// Many commands pipelined in one write, each followed by the query that shows it: every reply,
// in order, each query reflecting the command before it — bounded work per tick, so it may
// take several ticks.
TEST_F(ReadYourWrites, PipelinedCommandsAreEachSeenByTheQueryAfterThem) {
  std::string lines;
  for (int i = 0; i < 100; ++i) lines += "ASN\rBO\rAC " + std::to_string(i) + " 0 0\rBO\rASF\rBO\r";
  const std::uint64_t start = fw.kernel().tick();
  const Replies r = fw.exchange(lines, 600, 2000);
  ASSERT_EQ(r.size(), 600u);
  const std::uint64_t ticks = fw.kernel().tick() - start;
  std::printf("300 pipelined commands, each with its query: %llu ticks\n", static_cast<unsigned long long>(ticks));
  // About one command per tick: the kernel bounds triggered runs (2 per process per tick).
  EXPECT_LE(ticks, 400u);
  for (int i = 0; i < 100; ++i) {
    const std::size_t k = static_cast<std::size_t>(i) * 6;
    EXPECT_EQ(r[k], "ack");
    EXPECT_EQ(servo_of(r[k + 1]), 1) << i << ": " << r[k + 1];
    EXPECT_EQ(r[k + 2], "ack");
    EXPECT_EQ(posture_of(r[k + 3]), "S " + std::to_string(i) + " 0 0 1") << i;
    EXPECT_EQ(r[k + 4], "ack");
    EXPECT_EQ(servo_of(r[k + 5]), 0) << i << ": " << r[k + 5];
  }
}

// A stop byte behind lines that wait for their command's owner still acts in the activation
// that reads it; the lines before it are answered, in order.
TEST_F(ReadYourWrites, StopByteActsAtOnceBehindWaitingLines) {
  ASSERT_EQ(fw.ask("ASN"), "ack");
  ASSERT_EQ(fw.ask("AM 20 -20"), "ack");
  ASSERT_TRUE(fw.run_until([&] { return fw.wheels() == std::pair{20, -20}; }, 300));
  std::string lines;
  for (int i = 0; i < 50; ++i) lines += "AM 20 -20\rBO\r";
  fw.send_raw(lines + "\x18");
  fw.step();
  EXPECT_EQ(fw.wheels(), (std::pair{0, 0})) << "stop byte not acted on within one tick";
  const Replies r = fw.exchange("XE\r", 101, 200);
  ASSERT_EQ(r.size(), 101u);
  for (int i = 0; i < 50; ++i) EXPECT_EQ(servo_of(r[2 * i + 1]), 1) << i;
  EXPECT_EQ(emergency_of(r[100]), "E 0 1 stop-byte");
}

// The seed stamped the communication watchdog on every complete line, valid or not.
TEST_F(ReadYourWrites, EveryCompleteLineStampsTheLinkWatchdog) {
  fw.run_ticks(30);
  for (const char* line : {"Zz", "AM 1", "A", "BO"}) {
    const std::uint64_t before = fw.bb().link_status.reader().peek().last_message_tick;
    ASSERT_TRUE(fw.ask(line)) << line;
    EXPECT_GT(fw.bb().link_status.reader().peek().last_message_tick, before) << line;
    fw.run_ticks(3);
  }
}

}  // namespace
}  // namespace robuter

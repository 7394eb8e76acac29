// SPDX-License-Identifier: GPL-3.0-or-later
// Every seed message through the whole codec: reply formats and the port calls they make.
#include <gtest/gtest.h>

#include <numeric>
#include <string>

#include "tests/protocol/codec_harness.hpp"

namespace robuter::protocol::testing {
namespace {

// Space-joined numbers, as the replies write them.
template <class Array>
std::string join(const Array& values) {
  std::string s;
  for (auto v : values) s += " " + std::to_string(v);
  return s;
}

class Messages : public ::testing::Test {
 protected:
  void SetUp() override {
    for (std::size_t i = 0; i < kSensorCount; ++i) h.port.us[i] = static_cast<int>(100 * i);
    for (std::size_t i = 0; i < kSectorCount; ++i) {
      h.port.raw[i] = static_cast<int>(1000 + i);
      h.port.filtered[i] = static_cast<int>(2000 + i);
      h.port.differences[i] = static_cast<int>(i) - 36;
    }
  }
  Harness h;
};

TEST_F(Messages, BO) { EXPECT_EQ(h.ask("BO"), "S 1204 -3 12 1 1523"); }

TEST_F(Messages, BOServoOff) {
  h.port.servo = false;
  EXPECT_EQ(h.ask("BO"), "S 1204 -3 12 0 1523");
}

TEST_F(Messages, BU) { EXPECT_EQ(h.ask("BU"), "U" + join(h.port.us) + " 1 1523"); }

TEST_F(Messages, BV) {
  EXPECT_EQ(h.ask("BV"), "V 1204 -3 12 1" + join(h.port.us) + " 1523");
}

TEST_F(Messages, BC) { EXPECT_EQ(h.ask("BC"), "C 1523"); }

TEST_F(Messages, BT) { EXPECT_EQ(h.ask("BT"), "T 33"); }

TEST_F(Messages, BP) { EXPECT_EQ(h.ask("BP"), "P" + join(h.port.raw) + " 1523"); }

TEST_F(Messages, BF) { EXPECT_EQ(h.ask("BF"), "F" + join(h.port.filtered) + " 1523"); }

TEST_F(Messages, BD) { EXPECT_EQ(h.ask("BD"), "D" + join(h.port.differences) + " 1523"); }

TEST_F(Messages, PanTiltAbsentIsError) {
  h.port.has_pan_tilt = false;
  EXPECT_EQ(h.ask("BP"), "error");
  EXPECT_EQ(h.ask("BF"), "error");
  EXPECT_EQ(h.ask("BD"), "error");
}

TEST_F(Messages, WorstCaseNumbersFit) {
  h.port.raw.fill(-2147483647 - 1);
  h.port.now = std::numeric_limits<Ticks>::min();
  const std::string r = h.ask("BP");
  EXPECT_EQ(r.substr(0, 13), "P -2147483648");
  EXPECT_EQ(r.size(), 2 + 72 * 12 + 20u);
}

TEST_F(Messages, AM) {
  EXPECT_EQ(h.ask("AM 10 -5"), "ack");
  EXPECT_EQ(h.port.last_motion.left, 10);
  EXPECT_EQ(h.port.last_motion.right, -5);
}

TEST_F(Messages, AMRefusedByEmergency) {
  h.port.motion_result = PortResult::refused_emergency;
  EXPECT_EQ(h.ask("AM 10 10"), "error");
}

TEST_F(Messages, AMWithOneParameterIsErrorAndDoesNotMove) {
  EXPECT_EQ(h.ask("AM 10"), "error");
  EXPECT_EQ(h.port.motion_requests, 0);
}

TEST_F(Messages, ASNandASF) {
  h.port.last_servo = false;
  EXPECT_EQ(h.ask("ASN"), "ack");
  EXPECT_TRUE(h.port.last_servo);
  EXPECT_EQ(h.ask("ASF"), "ack");
  EXPECT_FALSE(h.port.last_servo);
  EXPECT_EQ(h.ask("ASX"), "error");
}

TEST_F(Messages, AYRefusedByDefault) {
  EXPECT_EQ(h.ask("AYPA6000"), "error");
  EXPECT_EQ(h.port.passed(), "PA6000");
}

TEST_F(Messages, AYAllowed) {
  h.port.pass_result = PortResult::ok;
  EXPECT_EQ(h.ask("AY X 1, 2"), "ack");
  EXPECT_EQ(h.port.passed(), " X 1, 2");
}

TEST_F(Messages, AC) {
  EXPECT_EQ(h.ask("AC 0,0,0"), "ack");
  EXPECT_EQ(h.ask("AC 10000 -2000 9000"), "ack");
  EXPECT_EQ(h.port.last_odometry.x, 10000);
  EXPECT_EQ(h.port.last_odometry.y, -2000);
  EXPECT_EQ(h.port.last_odometry.theta, 9000);
}

TEST_F(Messages, AW) {
  EXPECT_EQ(h.ask("AW 5000 0 -9000"), "ack");
  EXPECT_EQ(h.port.last_goal.x, 5000);
  EXPECT_EQ(h.port.last_goal.theta, -9000);
  h.port.result = PortResult::unavailable;
  EXPECT_EQ(h.ask("AW 5000 0 0"), "error");
}

TEST_F(Messages, AX) {
  EXPECT_EQ(h.ask("AX"), "ack");
  EXPECT_EQ(h.port.shutdowns, 1);
}

TEST_F(Messages, ModuleSwitches) {
  EXPECT_EQ(h.ask("Ap"), "ack");
  EXPECT_TRUE(h.port.pan_tilt_on);
  EXPECT_EQ(h.ask("Ag"), "ack");
  EXPECT_FALSE(h.port.pan_tilt_on);
  EXPECT_EQ(h.ask("AG"), "ack");
  EXPECT_TRUE(h.port.gate_on);
  EXPECT_EQ(h.ask("AT"), "ack");
  EXPECT_FALSE(h.port.gate_on);
  EXPECT_EQ(h.ask("Ad"), "ack");
  EXPECT_TRUE(h.port.doors_on);
  EXPECT_EQ(h.ask("Af"), "ack");
  EXPECT_FALSE(h.port.doors_on);
  EXPECT_EQ(h.ask("Ap 1"), "error");
}

// A robot without a pan-tilt unit: the port's no_unit is error, verbose 16 no-unit.
TEST_F(Messages, NoUnitIsErrorSixteen) {
  h.port.result = PortResult::no_unit;
  EXPECT_EQ(h.ask("Ap"), "error");
  h.port.result = PortResult::ok;
  EXPECT_EQ(h.ask("XB1"), "ack");
  h.port.result = PortResult::no_unit;
  for (const char* l : {"Ap", "AG", "Ad"}) EXPECT_EQ(h.ask(l), "error 16 no-unit") << l;
}

TEST_F(Messages, UT) {
  EXPECT_EQ(h.ask("UT111111111111111111111111"), "ack");
  EXPECT_EQ(h.port.last_table.count(), 24u);
  EXPECT_EQ(h.ask("UT010000000000000000000000"), "ack");
  EXPECT_TRUE(h.port.last_table.test(1));
  EXPECT_EQ(h.port.last_table.count(), 1u);
  EXPECT_EQ(h.ask("UT1011"), "error");
  EXPECT_EQ(h.port.last_table.count(), 1u);
}

TEST_F(Messages, UDandUN) {
  EXPECT_EQ(h.ask("UD5"), "ack");
  EXPECT_EQ(h.port.last_delay, 5);
  EXPECT_EQ(h.ask("UD"), "error");
  EXPECT_EQ(h.ask("UN"), "N 3");
}

TEST_F(Messages, USNandUSS) {
  EXPECT_EQ(h.ask("USN"), "S 4");
  EXPECT_EQ(h.ask("USS"), "S 29");
}

TEST_F(Messages, Ut) {
  EXPECT_EQ(h.ask("Ut33"), "ack");
  EXPECT_EQ(h.port.last_timeout, 33);
  EXPECT_EQ(h.ask("Ut 100"), "ack");
  EXPECT_EQ(h.port.last_timeout, 100);
}

TEST_F(Messages, Uu) {
  EXPECT_EQ(h.ask("Uu1"), "ack");
  EXPECT_TRUE(h.port.auto_toggle);
  EXPECT_EQ(h.ask("Uu0"), "ack");
  EXPECT_FALSE(h.port.auto_toggle);
}

TEST_F(Messages, PortRefusalsBecomeError) {
  h.port.result = PortResult::busy;
  for (const char* line : {"ASN", "AC 0 0 0", "Ap", "AG", "Ad", "UT111111111111111111111111",
                           "UD3", "Ut33", "Uu1", "XR", "AX"}) {
    EXPECT_EQ(h.ask(line), "error") << line;
  }
}

// As the seed's serial.c: every complete line, valid or not (not the stop byte, not a half line).
TEST_F(Messages, EveryCompleteLineStampsTheWatchdog) {
  h.ask("BC");
  h.ask("Zz");
  h.ask("AM 1");
  h.ask("AM 1 1");
  h.ask("A");
  EXPECT_EQ(h.port.messages, 5);
  h.feed("\x18" "BO");
  EXPECT_EQ(h.port.messages, 5);
  h.feed(std::string_view("\x00\r", 2));
  EXPECT_EQ(h.port.messages, 6);
}

TEST_F(Messages, WorkedExchangeOfTheSpec) {
  // protocol.md §4, byte for byte.
  EXPECT_EQ(h.ask("BC"), "C 1523");
  EXPECT_EQ(h.ask("ASN"), "ack");
  EXPECT_EQ(h.ask("AM 10 10"), "ack");
  EXPECT_EQ(h.ask("AM 10"), "error");
  h.port.now = 1540;
  EXPECT_EQ(h.ask("BO"), "S 1204 -3 12 1 1540");
  EXPECT_EQ(h.ask("UT111111111111111111111111"), "ack");
  EXPECT_EQ(h.ask("UT1011"), "error");
  EXPECT_EQ(h.ask("UN"), "N 3");
  EXPECT_EQ(h.ask("Zz"), "error");
}

TEST_F(Messages, WorkedExchangeInOneWrite) {
  h.port.now = 1540;
  const auto r = h.feed(
      "BC\rASN\rAM 10 10\rAM 10\rBO\rUT111111111111111111111111\rUT1011\rUN\rZz\r");
  const std::vector<std::string> expected = {"C 1540\r", "ack\r", "ack\r",
                                             "error\r",  "S 1204 -3 12 1 1540\r",
                                             "ack\r",    "error\r", "N 3\r", "error\r"};
  EXPECT_EQ(r, expected);
}

}  // namespace
}  // namespace robuter::protocol::testing

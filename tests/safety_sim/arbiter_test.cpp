// SPDX-License-Identifier: GPL-3.0-or-later
// The motion arbiter on the whole firmware: each operator command ends each automatic mode within
// one tick, nothing of the mode drives again (not after XR either) until its own start, and the
// door crossing's lowered detections never cover anyone else's motion.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "tests/safety_sim/support.hpp"

namespace robuter::test::safety_sim {
namespace {

const std::string kCourse = ROBUTER_SHIPPED_WORLDS "/seed002_course.toml";
const std::string kDoor = ROBUTER_SHIPPED_WORLDS "/door90.toml";

// XD's words, split ("D" first).
std::vector<std::string> xd(SimFirmware& fw) {
  std::vector<std::string> w;
  std::istringstream in(fw.ask("XD").value_or(""));
  for (std::string s; in >> s;) w.push_back(s);
  return w;
}

const MotionCommand& command(SimFirmware& fw) { return fw.bb().motion_command.reader().peek(); }
const MotionAuthority& authority(SimFirmware& fw) { return fw.bb().authority.reader().peek(); }

// Runs until the drive turns at `source`'s granted speeds; false after `max` ticks.
bool until_driving(SimFirmware& fw, MotionSource source, int max) {
  return fw.run_until([&] { return command(fw).source == source && !commanded(fw).zero(); }, max);
}

// Sends `bytes` (a line is asked: its reply is read) and returns the ticks from then until the
// arbiter took the robot from `mode` (-1: not within 50).
int ticks_to_end(SimFirmware& fw, MotionSource mode, const std::string& bytes) {
  const std::uint64_t t0 = fw.kernel().tick();
  if (bytes.back() == '\r') EXPECT_TRUE(fw.ask(bytes.substr(0, bytes.size() - 1))) << bytes;
  else fw.send_raw(bytes);
  if (!fw.run_until([&] { return authority(fw).owner != mode; }, 50)) return -1;
  return static_cast<int>(authority(fw).tick - t0);
}

// Ticks in `n` in which the drive ran speeds granted to `source`.
int driving_ticks(SimFirmware& fw, MotionSource source, int n) {
  int moving = 0;
  for (int i = 0; i < n; ++i) {
    fw.step();
    if (command(fw).source == source && !commanded(fw).zero()) ++moving;
  }
  return moving;
}

// The operator's commands that end a running mode, and how the mode then reports its end.
struct Interruption {
  const char* bytes;      // what the client sends
  const char* reason;     // XD's reason afterwards
  bool stop_byte;         // latches: XR afterwards
};
const Interruption kOperator[] = {
    {"AM 0 0\r", "operator", false}, {"ASF\r", "operator", false}, {"AW 0 0 0\r", "operator", false},
    {"\x18", "operator", true},      {"XH\r", "operator", false},  {"AT\r", "operator", false},
    {"Af\r", "operator", false},     {"XT0\r", "cancelled", false},
};

class DemoEndsOn : public ::testing::TestWithParam<Interruption> {};

// The demonstration (XT1) driving its course: the command takes the robot in the tick it is
// read, XD says why, the course never drives again — not after XR — until XT1.
TEST_P(DemoEndsOn, TheOperatorsCommand) {
  const Interruption& c = GetParam();
  Config cfg;
  cfg.emergency.comm_limit_ticks = 1'000'000;
  SimFirmware fw(kCourse, cfg);
  ASSERT_TRUE(fw.ok()) << fw.error();
  ASSERT_EQ(fw.ask("ASN"), "ack");
  ASSERT_EQ(fw.ask("XT1"), "ack");
  ASSERT_TRUE(until_driving(fw, MotionSource::demo, 3000)) << "the demonstration drives";
  fw.run_ticks(150);
  const int ticks = ticks_to_end(fw, MotionSource::demo, c.bytes);
  EXPECT_GE(ticks, 0);
  EXPECT_LE(ticks, 1) << "ended within one tick of the command";
  EXPECT_EQ(driving_ticks(fw, MotionSource::demo, 10), 0);  // (the mode reports at its next activation)
  const auto w = xd(fw);
  ASSERT_GE(w.size(), 13u);
  EXPECT_EQ(w[10], "failed");
  EXPECT_EQ(w[11], c.reason);
  if (c.stop_byte) {
    EXPECT_EQ(driving_ticks(fw, MotionSource::demo, 100), 0);
    fw.run_until([&] { return fw.ask("XR") == "ack"; }, 2000);
  }
  EXPECT_EQ(driving_ticks(fw, MotionSource::demo, 1500), 0) << "nothing of the course resumes";
  ASSERT_EQ(fw.ask("ASN"), "ack");
  EXPECT_EQ(driving_ticks(fw, MotionSource::demo, 300), 0) << "not even with the servo back on";
  ASSERT_EQ(fw.ask("XT1"), "ack");
  EXPECT_TRUE(until_driving(fw, MotionSource::demo, 3000)) << "its own start command starts it again";
}

INSTANTIATE_TEST_SUITE_P(Arbiter, DemoEndsOn, ::testing::ValuesIn(kOperator));

// [demo] enabled is an XT1 at start-up: the course drives, AM 0 0 ends it for good (the seed's
// program had no way to take the robot back).
TEST(Arbiter, TheDemonstrationFromStartUpEndsOnAmZero) {
  Config cfg;
  cfg.demo.enabled = true;
  SimFirmware fw(kCourse, cfg);
  ASSERT_TRUE(fw.ok()) << fw.error();
  ASSERT_TRUE(until_driving(fw, MotionSource::demo, 3000)) << "the executor powers the servo for its grant";
  EXPECT_LE(ticks_to_end(fw, MotionSource::demo, "AM 0 0\r"), 1);
  EXPECT_EQ(driving_ticks(fw, MotionSource::demo, 1000), 0);
  EXPECT_TRUE(commanded(fw).zero());
}

// Ad: the detections stay the operator's until the crossing is in the door; an operator's AM then
// takes the robot with the ultrasonic detection back on in the same activation.
TEST(Arbiter, TheDoorCrossingsLoweredDetectionsNeverCoverTheOperator) {
  Config cfg;
  SimFirmware fw(kDoor, cfg, {}, true);
  ASSERT_TRUE(fw.ok()) << fw.error();
  ASSERT_EQ(fw.ask("ASN"), "ack");
  ASSERT_EQ(fw.ask("Ap"), "ack");
  ASSERT_EQ(fw.ask("Ad"), "ack");
  EXPECT_EQ(fw.bb().emergency.reader().peek().enabled, 7) << "Ad alone lowers nothing";
  EXPECT_EQ(authority(fw).detections, 7);
  const auto in_door = [&] {
    const ModeState s = fw.bb().doors_status.reader().peek().state;
    return s == ModeState::crossing || s == ModeState::waiting || s == ModeState::leaving;
  };
  ASSERT_TRUE(fw.run_until(in_door, 20'000)) << "the crossing enters the door";
  fw.run_until([&] { return authority(fw).detections == 1; }, 20);
  EXPECT_EQ(authority(fw).detections, 1) << "bumper only while in the door (the seed's emerg.on = BUMPER)";
  ASSERT_EQ(fw.ask("AM 10 10"), "ack");
  fw.run_until([&] { return command(fw).source == MotionSource::link; }, 20);
  EXPECT_EQ(command(fw).source, MotionSource::link);
  EXPECT_EQ(fw.bb().emergency.reader().peek().enabled & 2, 2) << "the operator drives with the sonar on";
  EXPECT_EQ(authority(fw).detections, 7);
  fw.run_ticks(10);  // the crossing reports at its next activation
  EXPECT_EQ(xd(fw)[6], "operator");
  EXPECT_EQ(driving_ticks(fw, MotionSource::doors, 500), 0);
}

// XG: the planner's navigation ends on AM 0 0 within a tick, its requests are dropped from then on.
TEST(Arbiter, ThePlannersNavigationEndsOnAmZero) {
  Config cfg;
  SimFirmware fw(ROBUTER_SHIPPED_WORLDS "/seed000_lab.toml", cfg);
  ASSERT_TRUE(fw.ok()) << fw.error();
  ASSERT_EQ(fw.ask("ASN"), "ack");
  ASSERT_EQ(fw.ask("XG 25000 0"), "ack");
  ASSERT_TRUE(until_driving(fw, MotionSource::planner, 6000)) << "the planner drives";
  EXPECT_LE(ticks_to_end(fw, MotionSource::planner, "AM 0 0\r"), 1);
  EXPECT_EQ(driving_ticks(fw, MotionSource::planner, 1000), 0);
  const std::string xp = fw.ask("XP").value_or("");
  EXPECT_NE(xp.find("operator"), std::string::npos) << xp;
}

// The other automatic modes under issue #13's four interruptions (AM 0 0, ASF, AW, the stop byte):
// the passage finder (AG), the door crossing (Ad) and the planner (XG), each driving when the
// command comes; it ends within one tick, its status says `operator`, and nothing of it drives
// again — not after XR and ASN either — until its own start.
struct Mode {
  const char* name;            // for the test's name
  std::string world;           // where it runs
  bool pan_tilt;               // with the simulated pan-tilt unit
  std::vector<std::string> start;  // the commands that start it (acked)
  MotionSource source;         // whose requests it makes
  int status_word;             // XD's reason word of the mode (-1: XP's text instead)
};
const Mode kModes[] = {
    {"PassageFinder", kDoor, true, {"ASN", "AG"}, MotionSource::gate, 4},
    {"DoorCrossing", kDoor, true, {"ASN", "Ap", "Ad"}, MotionSource::doors, 6},
    {"Planner", ROBUTER_SHIPPED_WORLDS "/seed000_lab.toml", false, {"ASN", "XG 25000 0"}, MotionSource::planner, -1},
};

class ModeEndsOn : public ::testing::TestWithParam<std::tuple<Mode, Interruption>> {};

TEST_P(ModeEndsOn, TheOperatorsCommand) {
  const auto& [m, c] = GetParam();
  Config cfg;
  cfg.emergency.comm_limit_ticks = 1'000'000;
  SimFirmware fw(m.world, cfg, {}, m.pan_tilt);
  ASSERT_TRUE(fw.ok()) << fw.error();
  for (const std::string& l : m.start) ASSERT_EQ(fw.ask(l), "ack") << l;
  ASSERT_TRUE(until_driving(fw, m.source, 20'000)) << m.name << " drives";
  const int ticks = ticks_to_end(fw, m.source, c.bytes);
  EXPECT_GE(ticks, 0);
  EXPECT_LE(ticks, 1) << "ended within one tick of the command";
  EXPECT_EQ(driving_ticks(fw, m.source, 20), 0);  // (the mode reports at its next activation)
  if (m.status_word >= 0) {
    const auto w = xd(fw);
    ASSERT_GT(w.size(), static_cast<std::size_t>(m.status_word));
    EXPECT_EQ(w[static_cast<std::size_t>(m.status_word)], "operator") << fw.ask("XD").value_or("");
  } else {
    const std::string xp = fw.ask("XP").value_or("");
    EXPECT_NE(xp.find("operator"), std::string::npos) << xp;
  }
  if (c.stop_byte) {
    EXPECT_EQ(driving_ticks(fw, m.source, 100), 0);
    fw.run_until([&] { return fw.ask("XR") == "ack"; }, 2000);
  }
  EXPECT_EQ(driving_ticks(fw, m.source, 1500), 0) << "nothing of the mode resumes";
  ASSERT_EQ(fw.ask("ASN"), "ack");
  EXPECT_EQ(driving_ticks(fw, m.source, 300), 0) << "not even with the servo back on";
}

// The case's name: the mode and the command.
std::string mode_case_name(const ::testing::TestParamInfo<std::tuple<Mode, Interruption>>& info) {
  static const char* const kWhat[] = {"AmZero", "Asf", "Aw", "StopByte"};
  const Mode& mode = std::get<0>(info.param);
  const std::string_view bytes = std::get<1>(info.param).bytes;
  std::size_t k = 0;
  while (k < 4 && bytes != kOperator[k].bytes) ++k;
  return std::string(mode.name) + "_" + (k < 4 ? kWhat[k] : "Other");
}

INSTANTIATE_TEST_SUITE_P(Arbiter, ModeEndsOn,
                         ::testing::Combine(::testing::ValuesIn(kModes), ::testing::ValuesIn(kOperator, kOperator + 4)),
                         mode_case_name);

}  // namespace
}  // namespace robuter::test::safety_sim

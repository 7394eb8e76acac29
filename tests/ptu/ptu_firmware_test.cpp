// The PTU module in the whole firmware on the simulated robot, the unit emulated on its own pty:
// Ap/Ag, BP/BF/BD from the scan, XD, and a unit that vanishes or was never configured.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "tests/support/sim_firmware.hpp"

namespace robuter {
namespace {

const std::string kDoor90 = ROBUTER_WORLDS_DIR "/door90.toml";

// The integers of a reply after its letter.
std::vector<long> numbers(const std::string& reply) {
  std::istringstream in(reply.substr(1));
  std::vector<long> v;
  long x;
  while (in >> x) v.push_back(x);
  return v;
}

// The words of a reply.
std::vector<std::string> words(const std::string& reply) {
  std::istringstream in(reply);
  std::vector<std::string> v;
  std::string w;
  while (in >> w) v.push_back(w);
  return v;
}

TEST(PtuFirmware, ApScansEverySectorAndBpReportsIt) {
  test::SimFirmware fw(kDoor90, Config{}, {}, true);
  ASSERT_TRUE(fw.ok()) << fw.error();
  EXPECT_EQ(words(*fw.ask("XD"))[1], "off");
  EXPECT_EQ(fw.ask("Ap"), "ack");
  const bool two_passes = fw.run_until([&] { return fw.bb().pan_tilt_scan.reader().peek().sweeps >= 3; }, 2000);
  ASSERT_TRUE(two_passes);
  const auto d = words(*fw.ask("XD"));
  ASSERT_GE(d.size(), 11u);
  EXPECT_EQ(d[1], "scanning");
  EXPECT_EQ(d[2], "none");
  const auto p = numbers(*fw.ask("BP"));
  ASSERT_EQ(p.size(), 73u);
  // Facing the 90 cm door 1.5 m away: straight ahead looks through it (no echo: the cap,
  // corrected 2546); the wall left and right of it is 1.5 – 1.7 m away.
  EXPECT_EQ(p[0], 2546);
  for (int i : {2, 3, 4, 5, 6, 7, 66, 67, 68, 69, 70}) {
    EXPECT_GT(p[static_cast<std::size_t>(i)], 1450) << i;
    EXPECT_LT(p[static_cast<std::size_t>(i)], 2000) << i;
  }
  for (long v : p) EXPECT_GT(v, 0);
  const auto f = numbers(*fw.ask("BF"));
  const auto dd = numbers(*fw.ask("BD"));
  ASSERT_EQ(f.size(), 73u);
  ASSERT_EQ(dd.size(), 73u);
  for (std::size_t i = 0; i < 72; ++i) EXPECT_EQ(dd[i], f[(i + 1) % 72] - f[i]) << i;
}

TEST(PtuFirmware, AgStopsAndClears) {
  test::SimFirmware fw(kDoor90, Config{}, {}, true);
  ASSERT_TRUE(fw.ok()) << fw.error();
  EXPECT_EQ(fw.ask("Ap"), "ack");
  fw.run_ticks(600);
  EXPECT_EQ(fw.ask("Ag"), "ack");
  fw.run_ticks(10);
  EXPECT_EQ(words(*fw.ask("XD"))[1], "off");
  const auto p = numbers(*fw.ask("BP"));
  for (std::size_t i = 0; i < 72; ++i) EXPECT_EQ(p[i], 0) << i;
  const std::uint32_t readings = fw.bb().pan_tilt_scan.reader().peek().readings;
  fw.run_ticks(300);
  EXPECT_EQ(fw.bb().pan_tilt_scan.reader().peek().readings, readings);
}

// Unplugged while sweeping: reported within a few activations, the firmware carries on.
TEST(PtuFirmware, UnpluggedUnitIsReportedAndScanningStops) {
  test::SimFirmware fw(kDoor90, Config{}, {}, true);
  ASSERT_TRUE(fw.ok()) << fw.error();
  EXPECT_EQ(fw.ask("Ap"), "ack");
  fw.run_ticks(400);
  ASSERT_EQ(words(*fw.ask("XD"))[1], "scanning");
  fw.unplug_ptu();
  const std::uint64_t t0 = fw.kernel().tick();
  ASSERT_TRUE(fw.run_until([&] { return fw.bb().pan_tilt_status.reader().peek().state == ModeState::failed; }, 300));
  EXPECT_LE(fw.kernel().tick() - t0, 30u);
  const auto d = words(*fw.ask("XD"));
  EXPECT_EQ(d[1], "failed");
  EXPECT_EQ(d[2], "unit-lost");
  EXPECT_EQ(fw.ask("BC")->substr(0, 2), "C ");  // the link still answers
}

TEST(PtuFirmware, NoUnitConfiguredIsReported) {
  test::SimFirmware fw(kDoor90);
  ASSERT_TRUE(fw.ok()) << fw.error();
  EXPECT_EQ(fw.ask("Ap"), "ack");
  fw.run_ticks(10);
  const auto d = words(*fw.ask("XD"));
  EXPECT_EQ(d[1], "failed");
  EXPECT_EQ(d[2], "no-unit");
  const auto p = numbers(*fw.ask("BP"));
  ASSERT_EQ(p.size(), 73u);
  EXPECT_EQ(p[5], 0);
}

// The process never waits: its longest activation stays far below its 2 ms budget.
TEST(PtuFirmware, ActivationsAreShort) {
  test::SimFirmware fw(kDoor90, Config{}, {}, true);
  ASSERT_TRUE(fw.ok()) << fw.error();
  EXPECT_EQ(fw.ask("Ap"), "ack");
  fw.run_ticks(1000);
  const auto i = fw.kernel().find("ptu");
  ASSERT_TRUE(i);
  EXPECT_GT(fw.kernel().stats(*i).activations, 300u);
  EXPECT_EQ(fw.kernel().stats(*i).overruns, 0u);
}

}  // namespace
}  // namespace robuter

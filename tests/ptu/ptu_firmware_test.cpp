// SPDX-License-Identifier: GPL-3.0-or-later
// The PTU module in the whole firmware on the simulated robot, the unit emulated on its own pty or
// (robuterd --sim's default) wired inside the process: Ap/Ag, BP/BF/BD from the scan, XD, a unit
// that vanishes, and a robot without one (Ap, AG, Ad answer error no-unit).
#include <gtest/gtest.h>

#include <stdlib.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "hal/sitl/byte_pipe.hpp"
#include "modules/firmware/sim_firmware.hpp"

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

// The first pass from one end to the other: the start-up sequence, the move to the first end
// (−90.2°: sweeps 1), then the pass to the other (85.0°: sweeps 2) fires every 5° mark once, and
// each firing fills two sectors 180° apart — all 72.
bool one_sweep_done(test::SimFirmware& fw) { return fw.bb().pan_tilt_scan.reader().peek().sweeps >= 2; }
// 2.52 s a pass (docs/SIMULATOR.md), plus the start-up and the way to the first end.
constexpr int kOneSweepTicks = 600;

// `make run` is the whole robot: robuterd --sim without any pan-tilt option has the simulated
// unit, wired to the PTU module inside the process, and one Ap sweep fills BP.
TEST(PtuFirmware, DefaultSimHasItsUnitAndApFillsBpInOneSweep) {
  test::SimFirmware fw(kDoor90);
  ASSERT_TRUE(fw.ok()) << fw.error();
  ASSERT_NE(fw.firmware().ptu_pipe(), nullptr) << "the unit is wired in-process";
  EXPECT_EQ(fw.ask("XB1"), "ack");
  EXPECT_EQ(fw.ask("Ap"), "ack");
  ASSERT_TRUE(fw.run_until([&] { return one_sweep_done(fw); }, kOneSweepTicks));
  const auto d = words(*fw.ask("XD"));
  ASSERT_GE(d.size(), 3u);
  EXPECT_EQ(d[1], "scanning");
  EXPECT_EQ(d[2], "none");
  const auto p = numbers(*fw.ask("BP"));
  ASSERT_EQ(p.size(), 73u);
  for (std::size_t i = 0; i < 72; ++i) EXPECT_GT(p[i], 0) << "sector " << i << " filled by the first sweep";
  EXPECT_EQ(p[0], 2546);  // straight through the 90 cm door: no echo, the cap (as over the pty)
  for (int i : {2, 3, 66, 67, 68, 69, 70}) {
    EXPECT_GT(p[static_cast<std::size_t>(i)], 1450) << i;
    EXPECT_LT(p[static_cast<std::size_t>(i)], 2000) << i;
  }
}

// Nothing of the unit is on the filesystem, so simulated runs side by side never collide: two
// firmwares in one process scan at once, and the harness's folder holds only the command link.
TEST(PtuFirmware, TwoDefaultSimsScanSideBySide) {
  test::SimFirmware a(kDoor90), b(kDoor90);
  ASSERT_TRUE(a.ok()) << a.error();
  ASSERT_TRUE(b.ok()) << b.error();
  EXPECT_EQ(a.ask("Ap"), "ack");
  EXPECT_EQ(b.ask("Ap"), "ack");
  for (int i = 0; i < kOneSweepTicks && !(one_sweep_done(a) && one_sweep_done(b)); ++i) {
    a.step();
    b.step();
  }
  EXPECT_TRUE(one_sweep_done(a));
  EXPECT_TRUE(one_sweep_done(b));
  for (auto* fw : {&a, &b}) {  // the command link and its lock, nothing of the unit
    const auto dir = std::filesystem::path(fw->pty_path()).parent_path();
    for (const auto& e : std::filesystem::directory_iterator(dir))
      EXPECT_EQ(e.path().filename().string().rfind("robuter.pty", 0), 0u) << e.path();
  }
}

// The in-process unit pulled out while sweeping: unit-lost, as with a pty or a serial adapter.
TEST(PtuFirmware, InProcessUnitUnpluggedIsReported) {
  test::SimFirmware fw(kDoor90);
  ASSERT_TRUE(fw.ok()) << fw.error();
  EXPECT_EQ(fw.ask("Ap"), "ack");
  fw.run_ticks(400);
  ASSERT_EQ(words(*fw.ask("XD"))[1], "scanning");
  fw.unplug_ptu();
  const std::uint64_t t0 = fw.kernel().tick();
  ASSERT_TRUE(fw.run_until([&] { return fw.bb().pan_tilt_status.reader().peek().state == ModeState::failed; }, 300));
  EXPECT_LE(fw.kernel().tick() - t0, 30u);
  EXPECT_EQ(words(*fw.ask("XD"))[2], "unit-lost");
}

// robuterd --sim --no-ptu: the robot without a pan-tilt unit. What needs it is refused at once
// (error, verbose 16 no-unit) instead of acked and failed later; switching off stays ack.
TEST(PtuFirmware, WithoutAUnitApAgAdAnswerNoUnit) {
  FirmwareOptions opt;
  opt.sim = true;
  opt.sim_options.world_file = kDoor90;
  opt.sim_ptu = false;
  test::SimFirmware fw(Config{}, opt);
  ASSERT_TRUE(fw.ok()) << fw.error();
  EXPECT_EQ(fw.firmware().ptu_pipe(), nullptr);
  for (const char* l : {"Ap", "AG", "Ad"}) EXPECT_EQ(fw.ask(l), "error") << l;
  EXPECT_EQ(fw.ask("XB1"), "ack");
  for (const char* l : {"Ap", "AG", "Ad"}) EXPECT_EQ(fw.ask(l), "error 16 no-unit") << l;
  for (const char* l : {"Ag", "AT", "Af"}) EXPECT_EQ(fw.ask(l), "ack") << l;
  fw.run_ticks(10);
  const auto d = words(*fw.ask("XD"));
  EXPECT_EQ(d[1], "off");  // nothing was started
  EXPECT_EQ(d[2], "none");
  EXPECT_EQ(fw.bb().modes.reader().peek().pan_tilt, false);
  const auto p = numbers(*fw.ask("BP"));  // the module runs: BP answers, all zeros
  ASSERT_EQ(p.size(), 73u);
  for (std::size_t i = 0; i < 72; ++i) EXPECT_EQ(p[i], 0) << i;
}

// --ptu-pty alone serves the unit to someone else: the PTU module has none (no-unit).
TEST(PtuFirmware, UnitOnItsOwnPtyIsNotTheModulesUnit) {
  FirmwareOptions opt;
  opt.sim = true;
  opt.sim_options.world_file = kDoor90;
  char tmpl[] = "/tmp/robuter-ptu-own-XXXXXX";
  const std::string dir = ::mkdtemp(tmpl);
  opt.ptu_pty = dir + "/ptu.pty";
  {
    test::SimFirmware fw(Config{}, opt);
    ASSERT_TRUE(fw.ok()) << fw.error();
    EXPECT_EQ(fw.firmware().ptu_pipe(), nullptr);
    EXPECT_TRUE(std::filesystem::exists(opt.ptu_pty));
    EXPECT_EQ(fw.ask("XB1"), "ack");
    EXPECT_EQ(fw.ask("Ap"), "error 16 no-unit");
  }
  std::filesystem::remove_all(dir);
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

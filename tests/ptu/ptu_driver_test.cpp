// SPDX-License-Identifier: GPL-3.0-or-later
// The pan-tilt driver against the PTU emulator (in process, no pty) and against broken units:
// start-up sequence, full sweeps with every sector filled at its angle, silent / garbage /
// refusing / vanished units detected in ticks without ever blocking.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "hal/sitl/ptu_emulator.hpp"
#include "modules/ptu/ptu_driver.hpp"

namespace robuter::ptu {
namespace {

// A byte stream whose far end is the emulator (or nothing, or a scripted liar).
class FakePort final : public hal::ByteStream {
 public:
  enum class Mode { unit, silent, garbage, refuse, closed };
  explicit FakePort(hal::PtuEmulator& e) : emu_(e) {}
  const char* name() const override { return "fake ptu"; }
  int fd() const override { return -1; }
  hal::IoResult read(std::span<std::uint8_t> out) override {
    if (mode == Mode::closed) return {0, true};
    if (!canned_.empty()) {
      const std::size_t n = std::min(out.size(), canned_.size());
      std::copy_n(canned_.begin(), n, out.begin());
      canned_.erase(0, n);
      return {n, false};
    }
    return {emu_.read_output(out), false};
  }
  hal::IoResult write(std::span<const std::uint8_t> in) override {
    if (mode == Mode::closed) return {0, true};
    written.append(reinterpret_cast<const char*>(in.data()), in.size());
    if (mode == Mode::unit) inbox_.append(reinterpret_cast<const char*>(in.data()), in.size());
    if (mode == Mode::garbage) canned_ += "#@%?\r\n";
    if (mode == Mode::refuse) canned_ += "! Illegal Command\r\n";
    return {in.size(), false};
  }
  // The unit reads what arrived during the last tick (as the emulator's port is served first in
  // every tick of the firmware).
  void deliver() {
    emu_.feed(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(inbox_.data()), inbox_.size()));
    inbox_.clear();
  }
  bool reopen() override { return mode != Mode::closed; }
  bool connected() const override { return mode != Mode::closed; }

  Mode mode = Mode::unit;
  std::string written;  // everything the driver sent

 private:
  hal::PtuEmulator& emu_;
  std::string canned_;  // scripted replies waiting to be read
  std::string inbox_;   // bytes written, not yet read by the unit
};

// Channel 7 answers with ranges that encode the pan angle at firing: the sensor looking along
// angle + 90° (index 1) reports real 400 + 10·(angle + 90) mm, the other 200 + 10·(angle + 90),
// both through the seed's calibration line (measured = 0.96 real + 46).
class FakeRing final : public hal::SonarRing {
 public:
  explicit FakeRing(hal::PtuEmulator& e) : emu_(e) {}
  void configure(std::uint32_t, std::uint32_t) override {}
  bool fire(int node, std::uint8_t mask, std::uint32_t = 0) override {
    if (node != hal::kPanTiltChannel || mask != 0x3 || pending_) return false;
    pending_ = true;
    angle_ = emu_.angle_deg();
    ++fired;
    return true;
  }
  bool read(int node, hal::NodeRanges& out) override {
    if (node != hal::kPanTiltChannel || !pending_) return false;
    pending_ = false;
    auto measured = [](double real) { return static_cast<std::uint16_t>(std::lround(0.96 * real + 46.0)); };
    out = {measured(200.0 + 10.0 * (angle_ + 90.0)), measured(400.0 + 10.0 * (angle_ + 90.0)), 0, 0};
    return true;
  }
  int fired = 0;

 private:
  hal::PtuEmulator& emu_;
  bool pending_ = false;
  double angle_ = 0.0;
};

// Driver, unit and ring on a 10 ms tick; the driver steps every tick (it polls every 3).
struct Rig {
  hal::PtuEmulator emu;
  FakePort port{emu};
  FakeRing ring{emu};
  PtuDriver driver;
  std::uint64_t tick = 1;
  explicit Rig(bool with_port = true) : driver(with_port ? &port : nullptr, ring, PtuSettings{}) {}
  void run(int ticks) {
    for (int i = 0; i < ticks; ++i, ++tick) {
      emu.advance(0.010);
      port.deliver();
      driver.step(tick, SectorPose{});
    }
  }
  bool run_until(DriverState s, int max_ticks) {
    for (int i = 0; i < max_ticks && driver.state() != s; ++i) run(1);
    return driver.state() == s;
  }
};

// Polls are 30 ms apart (the seed's period) although the driver steps every tick.
TEST(PtuDriver, PollsEveryThirtyMilliseconds) {
  Rig r;
  r.driver.start(r.tick);
  ASSERT_TRUE(r.run_until(DriverState::scanning, 100));
  r.run(10);
  const std::size_t before = r.port.written.size();
  r.run(300);
  const std::string polls = r.port.written.substr(before);
  std::size_t n = 0;
  for (std::size_t p = polls.find("PP\r"); p != std::string::npos; p = polls.find("PP\r", p + 1)) ++n;
  EXPECT_GE(n, 95u);   // 300 ticks / 3, less the pp commands at the ends
  EXPECT_LE(n, 100u);
}

TEST(PtuDriver, StartUpSequenceIsTheSeeds) {
  Rig r;
  r.driver.start(r.tick);
  EXPECT_EQ(r.driver.state(), DriverState::starting);
  ASSERT_TRUE(r.run_until(DriverState::scanning, 100));
  EXPECT_EQ(r.port.written.substr(0, 30), "ED\rFT\rI\rPA6000\rps1500\rpp-1755\r");
  r.run(6);
  EXPECT_EQ(r.port.written.substr(r.port.written.size() - 3), "PP\r");  // then polling
  EXPECT_FALSE(r.emu.echo());
  EXPECT_FALSE(r.emu.verbose());
  EXPECT_EQ(r.emu.speed(), 1500);
  EXPECT_EQ(r.emu.acceleration(), 6000);
}

// Two whole passes: every sector read, each at its own angle within the seed's tolerance.
TEST(PtuDriver, SweepsAndFillsEverySectorAtItsAngle) {
  Rig r;
  r.driver.start(r.tick);
  ASSERT_TRUE(r.run_until(DriverState::scanning, 100));
  for (int i = 0; i < 2000 && r.driver.scan().sweeps < 3; ++i) r.run(1);
  ASSERT_GE(r.driver.scan().sweeps, 3u);  // to −1755, to 1655, back to −1755
  const PanTiltScan& s = r.driver.scan();
  for (int k = 0; k < 36; ++k) {
    const auto i = static_cast<std::size_t>(k);
    ASSERT_GT(s.read_tick[i], 0u) << k;
    ASSERT_GT(s.read_tick[i + 36], 0u) << k + 36;
    // raw = 400 + 10·(angle + 90): fired at the tick nearest 5k (0.4° at 1500 positions/s,
    // 0.77° a tick) → ±4 mm, +1 for rounding, +1 for truncation
    EXPECT_NEAR(s.raw[i], 400 + 50 * k, 6) << "sector " << k;
    EXPECT_NEAR(s.raw[i + 36], 200 + 50 * k, 6) << "sector " << k + 36;
    // and where it looked: angle + 90° for the first sonar, angle + 270° for the other
    EXPECT_NEAR(s.direction[i] / 100.0, 5.0 * k, 0.5) << "sector " << k;
    EXPECT_NEAR(s.direction[i + 36] / 100.0, 5.0 * k + 180.0, 0.5) << "sector " << k + 36;
  }
  EXPECT_GE(r.ring.fired, 72);
  // One pass takes 3410 positions at 1500/s plus the ramps: about 2.5 s, 250 ticks.
  EXPECT_EQ(r.driver.lost_echoes(), 0u);
  EXPECT_EQ(r.driver.timeouts(), 0u);
}

TEST(PtuDriver, FilteredAndDifferencesFollowEveryReading) {
  Rig r;
  r.driver.start(r.tick);
  r.run(800);
  const PanTiltScan& s = r.driver.scan();
  SectorValues f, d;
  spike_filter(s.raw, f);
  differences(f, d);
  EXPECT_EQ(f, s.filtered);
  EXPECT_EQ(d, s.differences);
}

TEST(PtuDriver, NoPortIsNoUnit) {
  Rig r(false);
  r.driver.start(r.tick);
  EXPECT_EQ(r.driver.state(), DriverState::failed);
  EXPECT_EQ(r.driver.fault(), DriverFault::no_unit);
}

// Three unanswered commands in a row (20 ticks each) fail the unit: within a second.
TEST(PtuDriver, SilentUnitIsDetectedInTicks) {
  Rig r;
  r.driver.start(r.tick);
  ASSERT_TRUE(r.run_until(DriverState::scanning, 100));
  r.run(30);
  r.port.mode = FakePort::Mode::silent;
  const std::uint64_t t0 = r.tick;
  ASSERT_TRUE(r.run_until(DriverState::failed, 200));
  EXPECT_EQ(r.driver.fault(), DriverFault::silent);
  EXPECT_LE(r.tick - t0, 3 * 24u);
  EXPECT_EQ(r.driver.timeouts(), 3u);
}

TEST(PtuDriver, SilentFromTheStart) {
  Rig r;
  r.port.mode = FakePort::Mode::silent;
  r.driver.start(r.tick);
  ASSERT_TRUE(r.run_until(DriverState::failed, 200));
  EXPECT_EQ(r.driver.fault(), DriverFault::silent);
  EXPECT_EQ(r.port.written, "ED\rED\rED\r");  // the first command, retried
}

TEST(PtuDriver, GarbageIsDetected) {
  Rig r;
  r.driver.start(r.tick);
  ASSERT_TRUE(r.run_until(DriverState::scanning, 100));
  r.run(30);
  r.port.mode = FakePort::Mode::garbage;
  ASSERT_TRUE(r.run_until(DriverState::failed, 100));
  EXPECT_EQ(r.driver.fault(), DriverFault::garbage);
}

TEST(PtuDriver, RefusalDuringStartUpFailsAtOnce) {
  Rig r;
  r.port.mode = FakePort::Mode::refuse;
  r.driver.start(r.tick);
  ASSERT_TRUE(r.run_until(DriverState::failed, 20));
  EXPECT_EQ(r.driver.fault(), DriverFault::refused);
}

TEST(PtuDriver, VanishedPortIsLostAndStaysFailed) {
  Rig r;
  r.driver.start(r.tick);
  ASSERT_TRUE(r.run_until(DriverState::scanning, 100));
  r.port.mode = FakePort::Mode::closed;
  r.run(3);
  EXPECT_EQ(r.driver.state(), DriverState::failed);
  EXPECT_EQ(r.driver.fault(), DriverFault::lost);
  r.driver.start(r.tick);
  EXPECT_EQ(r.driver.fault(), DriverFault::lost);
}

// Off: no command is sent and the scan is cleared; on again, polling resumes without the
// start-up sequence and the unit sweeps on.
TEST(PtuDriver, StopClearsAndRestartResumes) {
  Rig r;
  r.driver.start(r.tick);
  r.run(600);
  ASSERT_GT(r.driver.scan().readings, 0u);
  r.driver.stop();
  EXPECT_EQ(r.driver.state(), DriverState::off);
  EXPECT_EQ(r.driver.scan().raw[10], 0);
  const std::size_t sent = r.port.written.size();
  r.run(60);
  EXPECT_EQ(r.port.written.size(), sent);
  r.driver.start(r.tick);
  EXPECT_EQ(r.driver.state(), DriverState::scanning);
  const std::uint32_t readings = r.driver.scan().readings;
  r.run(300);
  EXPECT_GT(r.driver.scan().readings, readings);
  EXPECT_EQ(r.port.written.find("ED", sent), std::string::npos);
}

// A failed unit (not lost) is set up again from the start on the next start().
TEST(PtuDriver, RetryAfterSilenceRunsTheStartUpAgain) {
  Rig r;
  r.port.mode = FakePort::Mode::silent;
  r.driver.start(r.tick);
  ASSERT_TRUE(r.run_until(DriverState::failed, 200));
  r.port.mode = FakePort::Mode::unit;
  r.driver.start(r.tick);
  ASSERT_TRUE(r.run_until(DriverState::scanning, 100));
}

}  // namespace
}  // namespace robuter::ptu

// SPDX-License-Identifier: GPL-3.0-or-later
// Thousands of seeded random command sequences (AM, AS, AW, AC, UT, Uu, UD, XR, stop byte, mask
// changes, bumpers, drive faults, link silence) over random obstacle ranges. The fake drive checks
// every command as it arrives: no non-zero speed and no servo-on while an emergency holds, and
// nothing the emergency module did not grant. After every tick an emergency means a still robot.
#include <gtest/gtest.h>

#include <memory>
#include <random>

#include "tests/safety/rig.hpp"
#include "tests/support/sample.hpp"

namespace robuter::test {
namespace {

constexpr int kSequences = sample(3000, 300);  // random sequences (a tenth under the sanitizers)
constexpr int kTicks = 500;       // ticks per sequence

struct Totals {
  std::uint64_t moving_commands = 0;  // non-zero speeds that reached the drive
  std::uint64_t trips = 0;            // emergencies tripped
  std::uint64_t held_ticks = 0;       // ticks with a held motion
  std::uint64_t go_to_grants = 0;     // grants whose source was the go-to
};

// One sequence; returns false (with a message) at the first broken property.
testing::AssertionResult run_sequence(std::uint64_t seed, Totals& totals) {
  std::mt19937_64 rng(seed);
  auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  auto chance = [&](double p) { return std::uniform_real_distribution<double>(0, 1)(rng) < p; };

  // Half the sequences on the seed's watch-dog rule, half on the envelope (the scripted distances
  // have no geometry there: they only feed the grid random evidence).
  Config cfg = seed_config();
  if (seed % 2 == 1) cfg.emergency.rule = "envelope";
  cfg.emergency.latch = chance(0.6);
  cfg.emergency.comm_limit_ticks = static_cast<std::uint32_t>(pick(60, 400));
  cfg.emergency.motion_timeout_ms = chance(0.3) ? static_cast<std::uint32_t>(pick(200, 2000)) : 0;
  cfg.emergency.auto_toggle = chance(0.3);
  auto r = std::make_unique<Rig>(cfg);
  if (!r->ok) return testing::AssertionFailure() << "rig did not start";
  for (auto& w : r->ring.world) w = static_cast<std::uint16_t>(pick(150, 4000));

  std::uint32_t last_cmd_seq = 0;
  for (int t = 0; t < kTicks; ++t) {
    // Link traffic: one command now and then, silence sometimes long enough to trip.
    if (chance(0.08)) {
      switch (pick(0, 11)) {
        case 0: case 1: case 2: {
          const int kind = pick(0, 3);
          const int a = pick(-100, 100), b = pick(-100, 100);
          r->link.am(kind == 0 ? 0 : a, kind == 1 ? a : (kind == 0 ? 0 : b));
          break;
        }
        case 3: r->link.as(chance(0.5)); break;
        case 4: r->link.aw(pick(-20000, 20000), pick(-20000, 20000), pick(-17999, 18000), chance(0.9)); break;
        case 5: r->link.ac(pick(-20000, 20000), pick(-20000, 20000), pick(-17999, 18000)); break;
        case 6: r->link.ut(static_cast<std::uint32_t>(rng()) & 0xFFFFFFu); break;
        case 7: r->link.uu(chance(0.5)); break;
        case 8: r->link.ud(static_cast<std::uint32_t>(pick(0, 6))); break;
        case 9: r->link.xr(); break;
        case 10: r->emergency.set_enabled(static_cast<std::uint8_t>(pick(0, 7))); break;
        case 11: r->link.message(); break;
      }
    }
    if (chance(0.004)) {
      r->link.stop_byte();
      if (chance(0.5)) r->kernel.trigger(&r->emergency);
    }
    if (chance(0.01)) r->bumpers.state = chance(0.5) ? 1u : 0u;
    if (chance(0.003)) r->drive.set_health(chance(0.5) ? hal::DriveHealth::fault : hal::DriveHealth::ok);
    // The world changes: objects come close, echoes vanish (0 = no echo).
    if (chance(0.2)) {
      const int s = pick(0, 23);
      const int kind = pick(0, 9);
      r->ring.world[static_cast<std::size_t>(s)] =
          static_cast<std::uint16_t>(kind == 0 ? 0 : (kind < 4 ? pick(100, 600) : pick(600, 5000)));
    }
    if (chance(0.003)) r->ring.never_ready = !r->ring.never_ready;

    const std::uint64_t before = r->drive.commands();
    r->step();
    for (std::uint64_t i = before; i < r->drive.commands(); ++i) {
      const DriveCommand& c = r->drive.command(i);
      if (!c.servo_call && (c.left != 0 || c.right != 0)) ++totals.moving_commands;
    }
    if (r->drive.violations() != 0)
      return testing::AssertionFailure() << "seed " << seed << " tick " << r->kernel.tick() - 1 << ": "
                                         << r->drive.first_violation();
    const EmergencyState& e = r->state();
    if ((e.latched || e.held || e.cause != EmergencyCause::none || (e.protective && e.granted_pct == 0)) &&
        r->drive.moving())
      return testing::AssertionFailure() << "seed " << seed << " tick " << r->kernel.tick() - 1
                                         << ": the robot moves at the end of a tick while an emergency holds";
    if (e.held) ++totals.held_ticks;
    const MotionCommand& c = r->command();
    if (r->bb.motion_command.reader().generation() != last_cmd_seq) {
      last_cmd_seq = r->bb.motion_command.reader().generation();
      if (!c.stop && c.source == MotionSource::go_to && (c.left != 0 || c.right != 0)) ++totals.go_to_grants;
    }
  }
  totals.trips += r->state().trips;
  r->kernel.shutdown();
  if (r->drive.servo() || r->drive.moving())
    return testing::AssertionFailure() << "seed " << seed << ": servo still on after close";
  return testing::AssertionSuccess();
}

TEST(Property, NoSpeedReachesTheDriveWhileAnEmergencyHoldsAndNothingUngranted) {
  Totals totals;
  for (int s = 0; s < kSequences; ++s) {
    ASSERT_TRUE(run_sequence(static_cast<std::uint64_t>(s) * 7919u + 17u, totals));
  }
  // The sequences must really exercise motion, trips, holds and the go-to.
  // (thresholds per 3,000 sequences, scaled to the sample)
  const auto per = [](std::uint64_t n) { return n * kSequences / 3000u; };
  EXPECT_GT(totals.moving_commands, per(3000));
  EXPECT_GT(totals.trips, per(500));
  EXPECT_GT(totals.held_ticks, per(1000));
  EXPECT_GT(totals.go_to_grants, per(200));
  std::printf("moving commands %llu, trips %llu, held ticks %llu, go-to grants %llu\n",
              static_cast<unsigned long long>(totals.moving_commands), static_cast<unsigned long long>(totals.trips),
              static_cast<unsigned long long>(totals.held_ticks),
              static_cast<unsigned long long>(totals.go_to_grants));
}

}  // namespace
}  // namespace robuter::test

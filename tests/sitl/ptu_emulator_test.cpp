// SPDX-License-Identifier: GPL-3.0-or-later
// The PTU emulator: replies to every command of the seed's subset (echo, verbose and terse),
// errors and limits, byte-level framing, and pan motion against the closed-form trapezoid.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <string_view>

#include "hal/sitl/ptu_emulator.hpp"

namespace robuter::hal {
namespace {

// Feeds `text` and returns every reply byte it produced.
std::string say(PtuEmulator& u, std::string_view text) {
  u.feed(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
  std::string out(u.output_size(), '\0');
  u.read_output(std::span<std::uint8_t>(reinterpret_cast<std::uint8_t*>(out.data()), out.size()));
  return out;
}

// A unit already put in the seed's mode (echo off, terse), replies discarded.
PtuEmulator seed_mode_unit() {
  PtuEmulator u;
  say(u, "ED\rFT\rI\rPA6000\r");
  return u;
}

// What seed 002's ptu() does with a PP reply: skip two characters, atoi the rest up to the CR.
int seed_parse(const std::string& reply) {
  const std::string line = reply.substr(0, reply.find('\r'));
  return std::atoi(line.c_str() + 2);
}

TEST(PtuEmulator, PowersUpEchoingAndVerbose) {
  PtuEmulator u;
  EXPECT_TRUE(u.echo());
  EXPECT_TRUE(u.verbose());
  EXPECT_EQ(say(u, "PP\r"), "PP * Current Pan position is 0\r\n");
}

// The exact exchange of seed 002's init_ptu() and move_ptu(): every reply ends in CR (send2ptu
// reads up to byte 13), and ED's own reply is still echoed.
TEST(PtuEmulator, SeedInitialisationSequence) {
  PtuEmulator u;
  EXPECT_EQ(say(u, "ED\r"), "ED *\r\n");
  EXPECT_FALSE(u.echo());
  EXPECT_EQ(say(u, "FT\r"), "*\r\n");
  EXPECT_FALSE(u.verbose());
  EXPECT_EQ(say(u, "I\r"), "*\r\n");
  EXPECT_EQ(say(u, "PA6000\r"), "*\r\n");
  EXPECT_EQ(u.acceleration(), 6000);
  EXPECT_EQ(say(u, "ps1500\r"), "*\r\n");
  EXPECT_EQ(u.speed(), 1500);
  EXPECT_EQ(say(u, "pp-1755\r"), "*\r\n");
  EXPECT_EQ(u.target(), -1755);
  const std::string reply = say(u, "PP\r");
  EXPECT_EQ(reply, "* 0\r\n");
  EXPECT_EQ(seed_parse(reply), 0);
}

TEST(PtuEmulator, QueriesInBothFeedbackModes) {
  PtuEmulator u;
  say(u, "ED\r");
  EXPECT_EQ(say(u, "PS\r"), "* Target Pan speed is 1500 positions/sec\r\n");
  EXPECT_EQ(say(u, "PA\r"), "* Pan acceleration is 6000 positions/sec^2\r\n");
  EXPECT_EQ(say(u, "PP\r"), "* Current Pan position is 0\r\n");
  EXPECT_EQ(say(u, "FT\r"), "*\r\n");
  EXPECT_EQ(say(u, "PS\r"), "* 1500\r\n");
  EXPECT_EQ(say(u, "PA\r"), "* 6000\r\n");
  EXPECT_EQ(say(u, "PP\r"), "* 0\r\n");
  EXPECT_EQ(say(u, "FV\r"), "*\r\n");
  EXPECT_EQ(say(u, "PP\r"), "* Current Pan position is 0\r\n");
  EXPECT_EQ(say(u, "EE\r"), "*\r\n");
  EXPECT_EQ(say(u, "ps700\r"), "ps700 *\r\n");
}

TEST(PtuEmulator, LimitsAreAcceptedExactlyAndRefusedBeyond) {
  PtuEmulator u = seed_mode_unit();
  EXPECT_EQ(say(u, "pp1655\r"), "*\r\n");
  EXPECT_EQ(say(u, "pp-1755\r"), "*\r\n");
  EXPECT_EQ(say(u, "pp1656\r"), "! Maximum allowable Pan position is 1655\r\n");
  EXPECT_EQ(say(u, "pp-1756\r"), "! Minimum allowable Pan position is -1755\r\n");
  EXPECT_EQ(say(u, "pp99999999999\r"), "! Maximum allowable Pan position is 1655\r\n");
  EXPECT_EQ(u.target(), -1755);  // refused commands change nothing
  EXPECT_EQ(say(u, "ps5836\r"), "*\r\n");
  EXPECT_EQ(say(u, "ps5837\r"), "! Pan speed cannot exceed 5836 pos/sec\r\n");
  EXPECT_EQ(say(u, "ps0\r"), "! Pan speed cannot be below 1 pos/sec\r\n");
  EXPECT_EQ(say(u, "ps-100\r"), "! Pan speed cannot be below 1 pos/sec\r\n");
  EXPECT_EQ(u.speed(), 5836);
  EXPECT_EQ(say(u, "PA100001\r"), "! Pan acceleration cannot exceed 100000 pos/sec^2\r\n");
  EXPECT_EQ(say(u, "PA0\r"), "! Illegal Command Argument\r\n");
  EXPECT_EQ(u.acceleration(), 6000);
}

TEST(PtuEmulator, BadCommandsGetTheErrorLine) {
  PtuEmulator u = seed_mode_unit();
  EXPECT_EQ(say(u, "ppx\r"), "! Illegal Command Argument\r\n");
  EXPECT_EQ(say(u, "pp12x\r"), "! Illegal Command Argument\r\n");
  EXPECT_EQ(say(u, "pp-\r"), "! Illegal Command Argument\r\n");
  EXPECT_EQ(say(u, "ps+\r"), "! Illegal Command Argument\r\n");
  EXPECT_EQ(say(u, "pp+20\r"), "*\r\n");
  EXPECT_EQ(u.target(), 20);
  EXPECT_EQ(say(u, "XYZ\r"), "! Illegal Command\r\n");
  EXPECT_EQ(say(u, "P\r"), "! Illegal Command\r\n");
  EXPECT_EQ(say(u, "PQ\r"), "! Illegal Command\r\n");
  EXPECT_EQ(say(u, "E\r"), "! Illegal Command\r\n");
  EXPECT_EQ(say(u, "TP\r"), "! Tilt axis is not emulated\r\n");
  EXPECT_EQ(say(u, "S\r"), "! Slaved mode is not emulated\r\n");
  EXPECT_EQ(say(u, std::string(40, 'P') + "\r"), "! Illegal Command\r\n");
  EXPECT_EQ(say(u, "PP\r"), "* 0\r\n");  // the unit still answers after all that
}

TEST(PtuEmulator, FramingCaseAndSplitCommands) {
  PtuEmulator u = seed_mode_unit();
  EXPECT_EQ(say(u, "pp100 PS\n"), "*\r\n* 1500\r\n");  // space and LF delimit too
  EXPECT_EQ(say(u, "\r\n\r\n   "), "");               // empty commands are ignored
  EXPECT_EQ(say(u, "p"), "");
  EXPECT_EQ(say(u, "P"), "");
  EXPECT_EQ(say(u, "\r"), "* 0\r\n");                 // "pP" split over two writes
  EXPECT_EQ(say(u, "pS2000\r\n"), "*\r\n");           // CR LF: one reply
  EXPECT_EQ(u.speed(), 2000);
}

TEST(PtuEmulator, AnUnreadHostLosesRepliesNotMemory) {
  PtuEmulator u = seed_mode_unit();
  for (int i = 0; i < 1000; ++i) {
    const char cmd[] = "PP\r";
    u.feed(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(cmd), 3));
  }
  EXPECT_EQ(u.output_size(), PtuEmulator::kOutputCapacity);
  EXPECT_EQ(u.output_dropped(), 1000u * 5u - PtuEmulator::kOutputCapacity);
}

// Closed form of a move from rest to rest over `d` positions at speed v, acceleration a.
double trapezoid(double t, double d, double v, double a) {
  const double ramp = v / a, ramp_d = v * v / (2 * a);
  if (2 * ramp_d > d) {  // triangle
    const double tp = std::sqrt(d / a);
    if (t <= tp) return 0.5 * a * t * t;
    if (t >= 2 * tp) return d;
    const double r = 2 * tp - t;
    return d - 0.5 * a * r * r;
  }
  const double total = 2 * ramp + (d - 2 * ramp_d) / v;
  if (t <= ramp) return 0.5 * a * t * t;
  if (t <= total - ramp) return ramp_d + v * (t - ramp);
  if (t >= total) return d;
  const double r = total - t;
  return d - 0.5 * a * r * r;
}

TEST(PtuEmulator, MotionFollowsTheTrapezoidAtTheSetSpeed) {
  for (const double step : {0.001, 0.010, 0.030, 0.077}) {
    PtuEmulator u = seed_mode_unit();
    say(u, "ps1500\rpp1500\r");
    double t = 0.0;
    while (t < 1.4) {
      u.advance(step);
      t += step;
      EXPECT_NEAR(u.exact_position(), trapezoid(t, 1500.0, 1500.0, 6000.0), 1e-6) << "t " << t << " step " << step;
    }
    EXPECT_EQ(u.position(), 1500);
    EXPECT_FALSE(u.moving());
  }
  // Cruise: 1500 positions per second exactly (45 per 30 ms, the seed's < 3° per activation).
  PtuEmulator u = seed_mode_unit();
  say(u, "pp1655\r");
  u.advance(0.3);
  const double p0 = u.exact_position();
  u.advance(0.030);
  EXPECT_NEAR(u.exact_position() - p0, 45.0, 1e-9);
  EXPECT_NEAR(u.velocity(), 1500.0, 1e-9);
  EXPECT_LT(45.0 * kPtuDegreesPerPosition, 3.0);
}

TEST(PtuEmulator, ShortMovesAreTriangles) {
  PtuEmulator u = seed_mode_unit();
  say(u, "pp100\r");
  for (int i = 1; i <= 30; ++i) {  // 2·√(100/6000) = 0.258 s, never above 775 positions/s
    u.advance(0.01);
    EXPECT_NEAR(u.exact_position(), trapezoid(0.01 * i, 100.0, 1500.0, 6000.0), 1e-6);
    EXPECT_LE(std::abs(u.velocity()), 775.0);
  }
  EXPECT_EQ(u.position(), 100);
}

TEST(PtuEmulator, RetargetingWhileMovingBrakesAndComesBack) {
  PtuEmulator u = seed_mode_unit();
  say(u, "pp1000\r");
  u.advance(0.5);  // cruising upward at 1500
  const double at = u.exact_position();
  say(u, "pp0\r");
  double peak = at;
  for (int i = 0; i < 300; ++i) {
    u.advance(0.01);
    peak = std::max(peak, u.exact_position());
  }
  EXPECT_NEAR(peak - at, 1500.0 * 1500.0 / (2 * 6000.0), 1e-6);  // braking distance
  EXPECT_EQ(u.position(), 0);
  EXPECT_FALSE(u.moving());
}

TEST(PtuEmulator, LoweringTheSpeedMidMoveSlowsDown) {
  PtuEmulator u = seed_mode_unit();
  say(u, "pp1655\r");
  u.advance(0.5);
  say(u, "ps500\r");
  u.advance(1.0);
  EXPECT_NEAR(u.velocity(), 500.0, 1e-9);
  for (int i = 0; i < 500 && u.moving(); ++i) u.advance(0.01);
  EXPECT_EQ(u.position(), 1655);
}

// What seed 002's ptu() sees: a PP every 30 ms during a whole sweep, parsed its way; the reported
// position rises by at most 45 per activation, never passes the end, and reads exactly 1655 at
// the end (the seed turns round on position == 1655).
TEST(PtuEmulator, PositionQueryDuringASweep) {
  PtuEmulator u = seed_mode_unit();
  say(u, "ps1500\rpp-1755\r");
  for (int i = 0; i < 200 && u.moving(); ++i) u.advance(0.03);
  ASSERT_EQ(seed_parse(say(u, "PP\r")), -1755);
  say(u, "pp1655\r");
  int last = -1755, activations = 0;
  while (true) {
    u.advance(0.03);
    ++activations;
    const std::string reply = say(u, "PP\r");
    ASSERT_EQ(reply.substr(0, 2), "* ");
    const int p = seed_parse(reply);
    EXPECT_EQ(p, u.position());
    EXPECT_GE(p, last);
    EXPECT_LE(p - last, 46);  // 45 per 30 ms, plus the step being counted
    EXPECT_LE(p, 1655);
    last = p;
    if (p == 1655) break;
    ASSERT_LT(activations, 200);
  }
  // 3410 positions: 0.25 s ramps at each end and 3035 positions of cruise, 2.523 s in all.
  EXPECT_EQ(activations, static_cast<int>(std::ceil((0.5 + 3035.0 / 1500.0) / 0.03)));
  EXPECT_NEAR(u.angle_deg(), 1655 * 185.0 / 3600.0, 1e-9);
}

}  // namespace
}  // namespace robuter::hal

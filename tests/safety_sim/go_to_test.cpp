// SPDX-License-Identifier: GPL-3.0-or-later
// Acceptance 6: AW reaches 20 random reachable postures in worlds/empty.toml within 2 cm and 2°.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "hal/sim/rng.hpp"
#include "modules/executor/executor.hpp"
#include "tests/safety_sim/support.hpp"

namespace robuter::test::safety_sim {
namespace {

constexpr int kTargets = 20;
const executor::GoToSettings kTolerance{};  // the documented tolerances (docs/SAFETY.md §6): 2 cm, 2°

// An angle difference in 0.01° brought into (−18000, 18000].
int angle_diff(int a, int b) {
  int d = (a - b) % 36000;
  if (d > 18000) d -= 36000;
  if (d <= -18000) d += 36000;
  return d;
}

// Errors of one arrival.
struct Arrival {
  double odo_mm = 0, odo_deg = 0;    // BO against the target
  double true_mm = 0, true_deg = 0;  // the simulated true pose against the target
  double seconds = 0;                // simulated time to arrive
};

// Sends AW to each of 20 seeded targets (axle within ±1 m of the arena's centre, any heading:
// the body and its turning circle stay ≥ 1 m from the walls) and measures each arrival.
std::vector<Arrival> run_targets(bool odometry_noise) {
  std::vector<Arrival> out;
  hal::SimOptions opt;
  opt.odometry_noise = odometry_noise;
  opt.seed = 7;
  SimFirmware fw(ROBUTER_SHIPPED_WORLDS "/empty.toml", Config{}, opt);
  EXPECT_TRUE(fw.ok()) << fw.error();
  if (!fw.ok()) return out;
  SafetyMonitor mon;
  mon.attach(fw);
  auto* exec = fw.module<ExecutorModule>("executor");
  EXPECT_NE(exec, nullptr);
  if (!exec) return out;
  const sim::Pose origin = fw.sim().robot().pose();  // odometry (0, 0, 0) is the world start pose
  sim::Rng rng(2024);
  for (int i = 0; i < kTargets; ++i) {
    const int tx = static_cast<int>(std::lround(rng.uniform(-10000.0, 10000.0)));
    const int ty = static_cast<int>(std::lround(rng.uniform(-10000.0, 10000.0)));
    const int tt = static_cast<int>(std::lround(rng.uniform(-17999.0, 18000.0)));
    SCOPED_TRACE(testing::Message() << "AW " << tx << " " << ty << " " << tt);
    const double t0 = fw.seconds();
    EXPECT_EQ(fw.ask("AW " + std::to_string(tx) + " " + std::to_string(ty) + " " + std::to_string(tt)), "ack");
    EXPECT_TRUE(fw.run_until([&] { return exec->go_to().active(); }, 20)) << "the go-to never started";
    EXPECT_TRUE(fw.run_until([&] { return !exec->go_to().active(); }, 8000)) << "never arrived";
    EXPECT_EQ(exec->go_to().phase(), executor::GoToPhase::done) << "ended without arriving";
    const auto& robot = fw.sim().robot();
    fw.run_until([&] { return robot.wheel_speeds().left == 0.0 && robot.wheel_speeds().right == 0.0; }, 200);
    fw.run_ticks(10);
    Arrival a;
    a.seconds = fw.seconds() - t0;
    const auto bo = parse_bo(fw.ask("BO"));
    EXPECT_TRUE(bo);
    if (!bo) return out;
    a.odo_mm = std::hypot(bo->x - tx, bo->y - ty) / 10.0;
    a.odo_deg = std::abs(angle_diff(bo->theta, tt)) / 100.0;
    // The target in the world: the odometry frame starts at the world start pose.
    const double c = std::cos(origin.theta), s = std::sin(origin.theta);
    const double wx = origin.x + (c * tx - s * ty) / 10000.0, wy = origin.y + (s * tx + c * ty) / 10000.0;
    const sim::Pose& p = robot.pose();
    a.true_mm = std::hypot(p.x - wx, p.y - wy) * 1000.0;
    a.true_deg = std::abs(sim::rad_to_deg(sim::wrap_angle(p.theta - origin.theta - tt * sim::kPi / 18000.0)));
    EXPECT_LE(a.odo_mm * 10.0, kTolerance.position_tolerance) << "BO " << bo->x << " " << bo->y << " " << bo->theta;
    EXPECT_LE(a.odo_deg * 100.0, kTolerance.angle_tolerance) << "BO " << bo->x << " " << bo->y << " " << bo->theta;
    out.push_back(a);
  }
  EXPECT_EQ(fw.bb().emergency.reader().peek().trips, 0u) << "nothing in the empty arena trips a go-to";
  EXPECT_EQ(mon.violations(), 0u) << mon.first_violation;
  return out;
}

// Prints the errors of each arrival and the worst ones; returns {max odo mm, max odo °, max true mm, max true °}.
std::array<double, 4> report(const std::vector<Arrival>& v, const char* title) {
  std::array<double, 4> worst{};
  std::printf("%s\n  #   BO error        true-pose error   time\n", title);
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Arrival& a = v[i];
    std::printf("  %2zu  %5.1f mm %4.2f°  %6.1f mm %5.2f°  %5.1f s\n", i + 1, a.odo_mm, a.odo_deg, a.true_mm, a.true_deg,
                a.seconds);
    worst = {std::max(worst[0], a.odo_mm), std::max(worst[1], a.odo_deg), std::max(worst[2], a.true_mm),
             std::max(worst[3], a.true_deg)};
  }
  std::printf("  worst: BO %.1f mm %.2f°, true pose %.1f mm %.2f° (tolerance %.0f mm, %.0f°)\n", worst[0], worst[1],
              worst[2], worst[3], kTolerance.position_tolerance / 10.0, kTolerance.angle_tolerance / 100.0);
  return worst;
}

TEST(GoTo, AwReachesTwentyRandomPosturesWithinTheDocumentedTolerance) {
  const auto v = run_targets(false);
  ASSERT_EQ(v.size(), static_cast<std::size_t>(kTargets));
  const auto w = report(v, "AW, exact odometry:");
  // With exact odometry the true pose is where BO says (to rounding).
  EXPECT_LE(w[2], kTolerance.position_tolerance / 10.0 + 0.1);
  EXPECT_LE(w[3], kTolerance.angle_tolerance / 100.0 + 0.01);
  RecordProperty("max_bo_error_mm", std::to_string(w[0]));
  RecordProperty("max_bo_error_deg", std::to_string(w[1]));
  RecordProperty("max_true_error_mm", std::to_string(w[2]));
  RecordProperty("max_true_error_deg", std::to_string(w[3]));
}

TEST(GoTo, WithOdometryNoiseBoStillArrivesAndTheTruePoseDriftIsReported) {
  const auto v = run_targets(true);
  ASSERT_EQ(v.size(), static_cast<std::size_t>(kTargets));
  const auto w = report(v, "AW, odometry noise and slip on (the true pose drifts from BO):");
  RecordProperty("noisy_max_true_error_mm", std::to_string(w[2]));
  RecordProperty("noisy_max_true_error_deg", std::to_string(w[3]));
}

}  // namespace
}  // namespace robuter::test::safety_sim

// SPDX-License-Identifier: GPL-3.0-or-later
// Reaction-time trials: a generated arena with one box, the firmware driving at it, a per-tick probe.
#include "tests/safety_sim/reaction.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "hal/sim/rng.hpp"
#include "hal/sim/sonar.hpp"
#include "hal/sim/world_io.hpp"
#include "modules/emergency/obstacle_check.hpp"
#include "modules/emergency/watchdog_sets.hpp"
#include "tests/safety_sim/support.hpp"

namespace robuter::test::safety_sim {

namespace {
constexpr double kBoxX = 12.0;      // box centre, m (arena 16 × 8 m)
constexpr double kBoxY = 4.0;
constexpr double kAxleToFront = 0.695;  // m
constexpr double kAxleToRear = 0.330;   // m

// Whether a trial drives backwards (rear first): the box is then behind the robot.
bool backwards(const ReactionTrial& t) { return t.left + t.right < 0; }

// The axle pose that puts the leading face `d` metres before the box's near face (unrotated).
sim::Pose pose_before_box(const ReactionTrial& t, double d) {
  const double face = kBoxX - 0.5 * t.box_size;
  return backwards(t) ? sim::Pose{face - d - kAxleToRear, kBoxY, sim::kPi} : sim::Pose{face - d - kAxleToFront, kBoxY, 0.0};
}

// The arena, the box, and the start pose.
// The approach's start, or far from the box for a teleport.
sim::Pose start_pose(const ReactionTrial& t) {
  return t.teleport ? sim::Pose{2.5, kBoxY, backwards(t) ? sim::kPi : 0.0} : pose_before_box(t, t.distance);
}

std::string world_toml(const ReactionTrial& t) {
  const sim::Pose start = start_pose(t);
  return fmt::format(
      "[world]\nname = \"reaction\"\nunits = \"m\"\n"
      "[start]\nx = {:.4f}\ny = {:.4f}\nheading_deg = {:.3f}\n"
      "[[wall]]\nname = \"arena\"\npoints = [[0.0, 0.0], [16.0, 0.0], [16.0, 8.0], [0.0, 8.0]]\nclosed = true\n"
      "[[box]]\nname = \"box\"\ncenter = [{:.4f}, {:.4f}]\nsize = [{:.4f}, {:.4f}]\nangle_deg = {:.3f}\n",
      start.x, start.y, sim::rad_to_deg(start.theta), kBoxX, kBoxY + t.lateral, t.box_size, t.box_size, t.box_angle);
}

// The box alone (no arena): what a sensor would read from the box, to tell its echoes apart.
std::string box_only_toml(const ReactionTrial& t) {
  return fmt::format(
      "[world]\nname = \"box\"\nunits = \"m\"\n[start]\nx = {:.4f}\ny = {:.4f}\nheading_deg = {:.3f}\n"
      "[[box]]\nname = \"box\"\ncenter = [{:.4f}, {:.4f}]\nsize = [{:.4f}, {:.4f}]\nangle_deg = {:.3f}\n",
      start_pose(t).x, start_pose(t).y, sim::rad_to_deg(start_pose(t).theta), kBoxX, kBoxY + t.lateral, t.box_size,
      t.box_size, t.box_angle);
}
}  // namespace

ReactionTrial random_trial(std::uint64_t seed, bool teleport) {
  sim::Rng rng(seed * 7919 + (teleport ? 1 : 0));
  ReactionTrial t;
  t.seed = seed;
  t.teleport = teleport;
  const int speed = 10 + static_cast<int>(rng.uniform(0.0, 71.0));  // 10…80 cm/s
  const bool back = rng.uniform() < 0.25;
  t.left = t.right = back ? -speed : speed;
  t.box_size = rng.uniform(0.4, 1.0);
  t.box_angle = rng.uniform(-15.0, 15.0);
  t.lateral = rng.uniform(-0.25, 0.25);
  const double safety = emergency::safety_distance_mm(t.left, t.right, 220, 10) / 1000.0;
  t.distance = teleport ? rng.uniform(0.2, std::max(0.2, safety - 0.03)) : rng.uniform(safety + 0.2, 3.0);
  return t;
}

std::int64_t percentile(const std::vector<std::int64_t>& sorted, double p) {
  if (sorted.empty()) return 0;
  const auto rank = static_cast<std::size_t>(std::ceil(p * static_cast<double>(sorted.size())));
  return sorted[std::min(sorted.size() - 1, rank == 0 ? 0 : rank - 1)];
}

Config seed_ring_config(Config cfg) {
  cfg.sonar.schedule = "seed";
  ProcessOverride us;
  us.name = "us";
  us.period = 4;
  us.offset = 2;
  cfg.processes.push_back(us);
  return cfg;
}

ReactionResult run_trial(const ReactionTrial& t) { return run_trial(t, core_config()); }

ReactionResult run_trial(const ReactionTrial& t, const Config& cfg) {
  ReactionResult out;
  const std::string toml = world_toml(t);
  if (auto err = check_world(toml)) {
    out.error = *err;
    return out;
  }
  TempWorld file(toml);
  hal::SimOptions opt;
  opt.seed = t.seed;
  SimFirmware fw(file.path(), seed_rule_config(cfg), opt);
  if (!fw.ok()) {
    out.error = fw.error();
    return out;
  }
  auto& robot = fw.sim().robot();
  const auto geom = robot.params().geometry;
  sim::GridScratch scratch;
  scratch.prepare(fw.sim().world().segments().size());
  sim::SonarModel ideal(fw.sim().world(), fw.sim().ring_params());  // the ring without noise
  auto box_world = sim::parse_world_toml(box_only_toml(t), "box.toml", geom);
  if (!box_world) {
    out.error = "box-only world: " + box_world.error().message;
    return out;
  }
  sim::SonarModel box_only(box_world.value(), fw.sim().ring_params());  // echoes from the box alone
  Wheels last{};           // the drive's speeds at the end of the previous tick
  bool armed = false;      // the obstacle is there to be found (approach: always; teleport: once placed)
  // The probe: the first watch-dog reading under the safety distance of the speeds the drive
  // had, and the tick the drive's speeds went to zero — both seen at the end of each tick.
  fw.set_tick_observer([&] {
    const std::uint64_t tick = fw.kernel().tick() - 1;
    const Wheels now = commanded(fw);
    if (robot.bumper()) out.contact = true;
    if (armed && !last.zero() && out.read_tick == 0) {
      const std::uint32_t safety_mm = emergency::safety_distance_mm(last.left, last.right, 220, 10);
      const auto& r = fw.bb().ranges.reader().peek();
      if (out.appear_tick == 0 &&
          body_clearance_near(fw.sim().world(), geom, robot.pose(), 1.5, scratch) * 1000.0 <= safety_mm)
        out.appear_tick = tick;
      if (out.appear_tick != 0 && out.seen_tick == 0) {
        // A reading read this tick whose echo is the box's (noise is off; within 60 mm: a ring read up
        // to 4 ticks after its echo, at 80 cm/s, has moved 32 mm since).
        for (int s = 1; s <= 24 && out.seen_tick == 0; ++s) {
          const auto i = static_cast<std::size_t>(s - 1);
          if (r.read_tick[i] != tick || r.mm[i] == 0 || (r.no_echo & (1u << i)) != 0) continue;
          const double b = box_only.measure(robot.pose(), fw.sim().layout()[i]);
          if (b > 0.0 && std::abs(b * 1000.0 - r.mm[i]) <= 60.0) out.seen_tick = tick;
        }
      }
      const auto watch = emergency::watch_sensors(emergency::main_sensor(last.left, last.right, 600));
      for (int s : watch) {
        if (out.visible_tick != 0) break;
        const double m = ideal.measure(robot.pose(), fw.sim().layout()[static_cast<std::size_t>(s - 1)]);
        if (m > 0.0 && std::lround(m * 1000.0) <= static_cast<long>(safety_mm)) out.visible_tick = tick;  // as the ring rounds
      }
      for (int s : watch) {
        const auto i = static_cast<std::size_t>(s - 1);
        if (r.read_tick[i] == tick && r.mm[i] > 0 && r.mm[i] <= safety_mm) {
          out.read_tick = tick;
          out.sensor = s;
          out.range_mm = r.mm[i];
          out.safety_mm = safety_mm;
          break;
        }
      }
    }
    if (!last.zero() && now.zero() && out.stop_tick == 0) out.stop_tick = tick;
    last = now;
  });

  if (fw.ask(fmt::format("AM {} {}", t.left, t.right)) != "ack") {
    out.error = "AM refused";
    return out;
  }
  if (t.teleport) {
    // Up to speed in the open, then the obstacle "appears": the moving robot is placed in front
    // of the box and its wheels keep their command.
    fw.run_until([&] { return std::abs(robot.wheel_speeds().left * 100.0) >= std::abs(t.left) - 0.5; }, 400);
    if (commanded(fw).zero()) {
      out.error = "never moved before the teleport";
      return out;
    }
    robot.place(pose_before_box(t, t.distance));
    robot.command_cm_s(t.left, t.right);
    out.appear_tick = fw.kernel().tick();
    out.visible_tick = out.appear_tick;
  }
  armed = true;
  const auto& e = fw.bb().emergency.reader().peek();
  out.tripped = fw.run_until([&] { return e.latched; }, 6000);
  out.cause = e.cause;
  fw.run_until([&] { return robot.wheel_speeds().left == 0.0 && robot.wheel_speeds().right == 0.0; }, 300);
  fw.run_ticks(20);
  out.clearance_at_rest_mm = body_clearance(fw.sim().world(), geom, robot.pose()) * 1000.0;
  fw.set_tick_observer(nullptr);
  out.ran = true;
  return out;
}

}  // namespace robuter::test::safety_sim

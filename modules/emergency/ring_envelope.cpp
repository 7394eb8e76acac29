// SPDX-License-Identifier: GPL-3.0-or-later
// Ring envelope: postures into the pose history, readings into the grid, requests into verdicts.
#include "modules/emergency/ring_envelope.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>

#include "robot/model_geometry.hpp"
#include "robot/robot_model.hpp"

namespace robuter::emergency {

namespace {
constexpr double kMaxStepPerTick = 0.03;  // farther than any wheel speed moves the robot in a tick: AC, m
constexpr double kMaxTurnPerTick = 0.08;  // the same for the heading (3.3 rad/s turning in place), rad
}  // namespace

GridSettings grid_settings(const EmergencyConfig&) {
  GridSettings g;
  g.blanking = robot::kRobuter.ring.blanking;
  g.half_angle = robot::kRobuter.ring.half_angle;
  g.contradict_sight = 0.5 * g.half_angle;  // the cone's half-angle split evenly (docs/SAFETY.md §13, "Multipath")
  return g;
}

EnvelopeSettings envelope_settings(const EmergencyConfig& cfg, const RobotConfig& robot, double tick_s) {
  EnvelopeSettings e;
  e.front = robot.axle_to_front_mm / 1000.0;
  e.rear = (static_cast<double>(robot.length_mm) - robot.axle_to_front_mm) / 1000.0;
  e.half_width = robot.width_mm / 2000.0;
  e.margin = cfg.margin_mm / 1000.0;
  e.wheel_base = robot.wheel_base_mm / 1000.0;
  e.decel = std::max(1u, robot.max_decel_cm_s2) / 100.0;
  e.reversal_decel = std::max(1u, std::min(robot.max_accel_cm_s2, robot.max_decel_cm_s2)) / 100.0;
  e.reaction = cfg.reaction_ms / 1000.0;
  e.creep = cfg.creep_cm_s / 100.0;
  e.near = robot::kRobuter.ring.blanking;
  e.step = grid_settings(cfg).cell;
  e.free_age_ticks = static_cast<std::uint64_t>(std::ceil(cfg.free_age_ms / 1000.0 / tick_s));
  e.near_age_ticks = 4 * e.free_age_ticks;
  return e;
}

// The body and the near field are the envelope's; a cone's edge tolerance is a cell's diagonal.
StartBlindSettings start_blind_settings(const EnvelopeSettings& e) {
  StartBlindSettings s;
  static_cast<BodyBox&>(s) = e;
  s.edge = e.step * 1.4142135623730951;
  return s;
}

RingEnvelope::RingEnvelope(const EmergencyConfig& cfg, const RobotConfig& robot, double tick_s)
    : cfg_(cfg),
      robot_(robot),
      tick_s_(tick_s),
      grid_(grid_settings(cfg)),
      env_(envelope_settings(cfg, robot, tick_s)),
      start_(start_blind_settings(env_.settings())) {
  set_tick(tick_s);
}

void RingEnvelope::set_tick(double tick_s) {
  tick_s_ = tick_s;
  const EnvelopeSettings e = envelope_settings(cfg_, robot_, tick_s);
  env_.set_ages(e.free_age_ticks, e.near_age_ticks);
  // A certificate rules a cell out as an echo's reflector for as long as the sweep trusts it to
  // drive through that cell (docs/SAFETY.md §13, "Evidence").
  grid_.set_narrow_age(cfg_.narrow_arcs ? e.free_age_ticks : 0);
  grid_.set_single_age(static_cast<std::uint64_t>(std::ceil(cfg_.single_echo_ms / 1000.0 / tick_s)));
  // Evidence is kept from a reading along another line of sight for as long as a certificate
  // counts (docs/SAFETY.md §13, "Multipath").
  grid_.set_sight_age(e.free_age_ticks);
}

void RingEnvelope::observe(std::uint64_t tick, const Posture& posture, const UltrasonicRanges& ranges, bool at_rest) {
  tick_ = tick;
  if (posture.tick != posture_tick_) {
    posture_tick_ = posture.tick;
    const Pose2 p{{posture.x / 10000.0, posture.y / 10000.0}, posture.theta / 100.0 * robot::kDeg};
    const bool first = history_.empty();
    const Pose2 before = first ? p : history_.at(posture.tick);  // the same moment in the old frame
    if (!history_.add(posture.tick, p, kMaxStepPerTick, kMaxTurnPerTick) || first) {
      // A new odometry frame (AC): the robot did not move, its coordinates did. The obstacle
      // evidence is carried into the new frame (the box it came to rest against is still there,
      // inside the blanking range where no reading can see it again); free space and the start
      // pose are certified again. The first posture: nothing is known yet.
      if (!first) {
        ++resets_;
        const Eigen::Matrix2d rot = Eigen::Rotation2Dd(p.theta - before.theta).toRotationMatrix();
        grid_.carry(rot, p.p - rot * before.p, p.p);
      } else {
        grid_.reset();
      }
      start_.reset();
      cones_.fill(SeenCone{});  // of the old frame
      reset_tick_ = posture.tick;
    }
  }
  if (history_.empty()) return;
  now_ = history_.at(tick);
  grid_.follow(now_.p);
  grid_.update_structure();
  // The new readings: every cone first, then every arc, so an arc is narrowed by what the whole
  // batch saw through (docs/SAFETY.md §13, "Evidence").
  struct Fresh {
    int sensor;                // 1..24
    std::uint64_t read;        // its read tick
    Eigen::Vector2d origin;    // the transducer, odometry frame, m
    double direction;          // the cone's axis, rad
    double range;              // m
    bool no_echo;              // nothing came back
  };
  std::array<Fresh, kSensors> fresh;
  std::size_t count = 0;
  for (int s = 1; s <= kSensors; ++s) {
    const auto i = static_cast<std::size_t>(s - 1);
    const std::uint64_t read = ranges.read_tick[i];
    if (read == seen_[i]) continue;
    seen_[i] = read;
    const std::uint32_t bit = 1u << i;
    if (ranges.mm[i] == 0 || read < reset_tick_) continue;  // no data, or from an old frame
    last_reading_ = std::max(last_reading_, read);
    const Pose2 at = history_.at(read);
    const robot::SonarMount& m = robot::kRobuter.ring.sensor(s).mount;
    fresh[count++] = Fresh{s, read, to_world(at, robot::position(m)), at.theta + m.direction, ranges.mm[i] / 1000.0,
                           (ranges.no_echo & bit) != 0};
  }
  // A no-echo certifies free space but never contradicts obstacle evidence: it may be a lost
  // echo, or a face too oblique to echo — the random sequences found a box whose evidence two
  // no-echoes in a row had cleared (seed 1631, docs/SAFETY.md §13). Only an echo from farther
  // away, or the body itself, clears evidence.
  for (std::size_t k = 0; k < count; ++k) {
    const Fresh& f = fresh[k];
    grid_.certify_cone(f.read, f.origin, f.direction, f.range, f.no_echo, !f.no_echo);
  }
  for (std::size_t k = 0; k < count; ++k) {
    const Fresh& f = fresh[k];
    if (f.no_echo) continue;
    const auto i = 2 * static_cast<std::size_t>(f.sensor - 1);
    cones_[i + 1] = cones_[i];
    cones_[i] = SeenCone{f.read, f.origin, f.direction, f.range};
  }
  for (std::size_t k = 0; k < count; ++k) {
    const Fresh& f = fresh[k];
    grid_.mark_arc(f.read, f.origin, f.direction, f.range, f.no_echo, cones_);
  }
  start_.observe(tick, now_, at_rest, ranges.scans, ranges.read_tick.data(), kSensors);
  if (tick != body_tick_) {
    body_tick_ = tick;
    const double front = robot_.axle_to_front_mm / 1000.0, rear = (robot_.length_mm - robot_.axle_to_front_mm) / 1000.0;
    const double half = robot_.width_mm / 2000.0;
    grid_.certify_rectangle(tick, now_.p, now_.theta, {-rear, -half}, {front, half});
  }
}

// A request that reverses a wheel lets the robot go on along its present arc first, slowing at
// the acceleration limit only (the drive's ramps): that braking must be clear of obstacles too.
EnvelopeVerdict RingEnvelope::judge(std::int32_t left, std::int32_t right, bool bumpers) {
  EnvelopeVerdict v;
  if (history_.empty()) {
    v.fraction = 0.0;
    v.missing = true;
    return v;
  }
  const double l = left / 100.0, r = right / 100.0;
  // A creep through blind space, and the longer life of the near field's certificates, need a
  // ring that is reading (a dead ring holds); the creep needs the bumpers armed too: nothing else
  // senses there (seed 1631 crept into a box with them masked off).
  const bool alive = last_reading_ != 0 && tick_ - last_reading_ <= env_.settings().free_age_ticks;
  v = env_.judge(grid_, now_, l, r, tick_, &start_, alive, bumpers);
  const Twist2 t = history_.velocity();
  const double speed = t.v / tick_s_, turn = t.w / tick_s_;
  const double half_base = 0.5 * robot_.wheel_base_mm / 1000.0;
  const double lc = speed - turn * half_base, rc = speed + turn * half_base;
  const bool reverses = (lc * l < 0.0 && std::abs(lc) > 0.01) || (rc * r < 0.0 && std::abs(rc) > 0.01);
  if (reverses && env_.braking_meets_obstacle(grid_, now_, speed, turn, env_.settings().reversal_decel, tick_)) {
    v.fraction = 0.0;
    v.obstacle = true;
  }
  return v;
}

}  // namespace robuter::emergency

// SPDX-License-Identifier: GPL-3.0-or-later
// The simulated robot behind the HAL: world loading, physics stepping, firing timing of the ring.
#include "hal/sitl/sim_robot.hpp"

#include <algorithm>
#include <cmath>

#include "hal/sim/sim_config.hpp"
#include "hal/sim/sonar_timing.hpp"
#include "hal/sim/world_io.hpp"
#include "kernel/sim_section.hpp"

namespace robuter::hal {

namespace {
constexpr double kPi = 3.14159265358979323846;

// The command line's odometry noise on top of the parameters.
void add_noise(const SimOptions& opt, sim::SimConfig& c) {
  if (opt.odometry_noise) {
    c.robot.odometry.noise = 0.002;
    c.robot.odometry.scale_left = 0.002;
    c.robot.odometry.scale_right = -0.002;
    c.robot.odometry.slip_sigma = 0.002;
  }
}
}  // namespace

sim::SimConfig firmware_sim_defaults(const Config& cfg) {
  const robot::RobotModel m = robot_model(cfg);
  sim::SimConfig c;
  c.robot.geometry = {m.body.length, m.body.width, m.body.axle_to_front, m.wheels.base};
  c.robot.limits.max_wheel_speed = m.wheels.max_speed;
  c.robot.limits.max_accel = m.wheels.max_accel;
  c.robot.limits.max_decel = 2.0 * m.wheels.max_accel;
  c.ring.timeout = cfg.sonar.timeout_ms / 1000.0;
  c.ring.sound_speed = cfg.sonar.sound_speed_m_s;
  c.ring.half_angle = m.ring.half_angle;
  c.pan_tilt.half_angle = m.pan_tilt.half_angle;
  c.pan_tilt_mount.pivot = {m.pan_tilt.pivot_x, 0.0};
  c.pan_tilt_mount.sensor_offset = m.pan_tilt.face_offset;
  return c;
}

sim::Result<sim::SimConfig> simulated_robot_config(const Config& cfg, const SimOptions& opt) {
  sim::SimConfig c = firmware_sim_defaults(cfg);
  // The sonar model first: a configuration's [sim.sonar] / [sim.pan_tilt] keys are the last word.
  for (sim::SonarParams* p : {&c.ring, &c.pan_tilt}) sim::apply_sonar_preset(opt.sonar_model, *p);
  if (cfg.sim) {
    auto applied = sim::apply_sim_config(*cfg.sim->table, cfg.source, c, "sim.");
    if (!applied) return applied.error();
    c = std::move(applied).value();
  }
  add_noise(opt, c);
  c.robot.odometry.seed = opt.seed;  // --seed seeds every random source (the [sim] seeds too)
  // The odometry is the firmware's: its own wheel base turns encoder travel into a pose.
  c.robot.odometry_wheel_base = robot_model(cfg).wheels.base;
  c.ring.ranging_speed = cfg.sonar.sound_speed_m_s;
  if (opt.adjust) opt.adjust(c);
  return c;
}

SimRobot::SimRobot(const Config& cfg, const SimOptions& opt)
    : ptu_(opt.ptu), rng_(opt.seed) {
  auto composed = simulated_robot_config(cfg, opt);
  if (!composed) {
    error_ = composed.error().describe();
    return;
  }
  const sim::SimConfig& c = composed.value();
  const std::string file = opt.world_file.empty() ? std::string(ROBUTER_DEFAULT_WORLD) : opt.world_file;
  auto loaded = sim::load_world(file, c.robot.geometry);
  if (!loaded) {
    error_ = "world: " + loaded.error().describe();
    return;
  }
  world_ = std::make_unique<sim::World>(std::move(loaded).value());
  robot_ = std::make_unique<sim::Robot>(*world_, c.robot, world_->start.value_or(sim::Pose{}));
  robot_->set_odometry(sim::Pose{});  // odometry starts at 0,0,0 like the real robot's
  sonar_ = std::make_unique<sim::SonarModel>(*world_, c.ring);
  pan_tilt_sonar_ = std::make_unique<sim::SonarModel>(*world_, c.pan_tilt);
  pan_tilt_mount_ = c.pan_tilt_mount;
  layout_ = c.layout;
}

// Seed ptu.c: pt_values[(angle + 90) / 5] = temp[1], pt_values[... + 36] = temp[0].
double SimRobot::pan_tilt_direction(double angle_deg) { return (angle_deg + 90.0) * kPi / 180.0; }

void SimRobot::advance_to(double t_s) {
  if (!robot_ || t_s <= time_) return;
  robot_->step(t_s - time_);
  ptu_.advance(t_s - time_);
  time_ = t_s;
}

void SimDrive::set_servo(bool on) {
  r_.servo_ = on;
  if (!on) {
    r_.left_ = r_.right_ = 0;
    r_.robot_->command_cm_s(0, 0);
  }
}

bool SimDrive::servo() const { return r_.servo_; }

void SimDrive::command_wheels(std::int32_t left_cm_s, std::int32_t right_cm_s) {
  if (!r_.servo_) return;
  r_.left_ = left_cm_s;
  r_.right_ = right_cm_s;
  r_.robot_->command_cm_s(left_cm_s, right_cm_s);
}

void SimDrive::commanded(std::int32_t& left_cm_s, std::int32_t& right_cm_s) const {
  left_cm_s = r_.left_;
  right_cm_s = r_.right_;
}

Odometry SimDrive::odometry() const {
  const sim::Pose& p = r_.robot_->odometry();
  return {p.x, p.y, sim::wrap_angle(p.theta)};
}

void SimDrive::set_odometry(const Odometry& o) { r_.robot_->set_odometry(sim::Pose{o.x_m, o.y_m, o.theta_rad}); }

void SimSonarRing::configure(std::uint32_t timeout_ms, std::uint32_t sound_speed_m_s) {
  sim::SonarParams p = r_.sonar_->params();
  p.timeout = timeout_ms / 1000.0;
  p.ranging_speed = sound_speed_m_s;
  r_.sonar_->set_params(p);
}

// Measured when fired: the echo comes from where the body was then (the robot moves ≤ 3 cm in
// a 33 ms time-out). The node reports when its last echo is in — echo time 2·range / c with the
// node's own speed of sound, the inverse of the range it reports — or at the firing's time-out
// when a fired sensor heard nothing within it.
bool SimSonarRing::fire(int node, std::uint8_t mask, std::uint32_t timeout_ms) {
  if (node == kPanTiltChannel) return r_.fire_pan_tilt(mask);
  if (node < 0 || node >= kSonarNodes) return false;
  auto& f = r_.firings_[static_cast<std::size_t>(node)];
  const sim::SonarParams& p = r_.sonar_->params();
  const double timeout = timeout_ms > 0 ? std::min(p.timeout, timeout_ms / 1000.0) : p.timeout;
  const double c = p.ranging_speed > 0.0 ? p.ranging_speed : p.sound_speed;
  // The fired sensors are measured together: node-mates may hear each other (cross-talk).
  std::array<sim::SonarMount, kSensorsPerNode> fired;
  std::array<double, kSensorsPerNode> ranges{};
  std::size_t n = 0;
  for (int i = 0; i < kSensorsPerNode; ++i) {
    if (mask & (1u << i)) fired[n++] = r_.layout_[static_cast<std::size_t>(sensor_number(node, i) - 1)];
  }
  r_.sonar_->measure_firing(r_.robot_->pose(), std::span<const sim::SonarMount>(fired.data(), n),
                            std::span<double>(ranges.data(), n), &r_.rng_);
  double last_echo = 0.0;
  for (int i = 0, k = 0; i < kSensorsPerNode; ++i) {
    auto& out = f.mm[static_cast<std::size_t>(i)];
    out = 0;
    if (!(mask & (1u << i))) continue;
    const double m = std::max(0.0, ranges[static_cast<std::size_t>(k++)]);
    const double echo = sim::echo_time(m, c);
    if (m <= 0.0 || echo > timeout) {
      last_echo = timeout;  // nothing heard in time: the node listens to the end
      continue;
    }
    out = static_cast<std::uint16_t>(std::lround(m * 1000.0));
    last_echo = std::max(last_echo, echo);
  }
  f.pending = true;
  f.mask = mask;
  f.ready_s = r_.time_ + last_echo;
  return true;
}

bool SimSonarRing::read(int node, NodeRanges& out) {
  if ((node < 0 || node >= kSonarNodes) && node != kPanTiltChannel) return false;
  auto& f = r_.firings_[static_cast<std::size_t>(node)];
  if (!f.pending || r_.time_ + 1e-9 < f.ready_s) return false;
  f.pending = false;
  if (node == kPanTiltChannel) {
    out = {f.pan_tilt_mm[0], f.pan_tilt_mm[1], 0, 0};
    return true;
  }
  out = f.mm;
  return true;
}

// Why measure at firing: the pan axis moves ~1° during the 15 ms listening time, and the echo
// comes from where the transducers pointed when they fired.
bool SimRobot::fire_pan_tilt(std::uint8_t mask) {
  if (mask & ~0x3u) return false;  // the pan-tilt carries two sonars
  auto& f = firings_[static_cast<std::size_t>(kPanTiltChannel)];
  const double angle = ptu_.angle_deg();
  const sim::PanTiltReading m = sim::measure_pan_tilt(*pan_tilt_sonar_, robot_->pose(), pan_tilt_mount_,
                                                      pan_tilt_direction(angle), &rng_);
  auto to_mm = [](double metres) {
    return static_cast<std::uint16_t>(std::lround(std::clamp(metres, 0.0, 60.0) * 1000.0));
  };
  f.pan_tilt_mm = {static_cast<std::uint16_t>((mask & 1u) ? to_mm(m.opposite) : 0),
                   static_cast<std::uint16_t>((mask & 2u) ? to_mm(m.facing) : 0)};
  f.pending = true;
  f.mask = mask;
  f.ready_s = time_ + pan_tilt_sonar_->params().timeout;
  last_pan_tilt_ = {true, time_, angle, f.pan_tilt_mm};
  return true;
}

std::uint32_t SimBumpers::pressed() const { return r_.robot_->bumper() ? 1u : 0u; }

}  // namespace robuter::hal

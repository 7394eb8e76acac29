// SPDX-License-Identifier: GPL-3.0-or-later
// Stop, scan, estimate, manoeuvre, scan again: the passage finder as a state machine.
#include "modules/gate/gate_logic.hpp"
#include "robot/robot_model.hpp"

#include <cmath>
#include <numbers>

namespace robuter::gate {

namespace {

executor::GoToSettings manoeuvre_settings(const GateSettings& s) {
  executor::GoToSettings g;
  g.position_tolerance = 100;  // 1 cm, 0.1 mm
  g.angle_tolerance = 50;      // 0.5°, 0.01°
  g.max_drive_cm_s = s.speed_cm_s;
  g.max_turn_cm_s = s.turn_cm_s;
  g.min_cm_s = 1;
  g.wheel_base_mm = s.wheel_base_mm;
  return g;
}

// A pose and a robot-frame offset (mm, degrees) composed into odometry units (0.1 mm, 0.01°).
executor::PostureUnits compose(const SectorPose& p, double x_mm, double y_mm, double dtheta_deg) {
  const double th = p.theta * 0.01 * robot::kDeg;
  executor::PostureUnits t;
  t.x = static_cast<std::int32_t>(std::lround(p.x + 10.0 * (x_mm * std::cos(th) - y_mm * std::sin(th))));
  t.y = static_cast<std::int32_t>(std::lround(p.y + 10.0 * (x_mm * std::sin(th) + y_mm * std::cos(th))));
  t.theta = executor::wrap_centideg(static_cast<std::int64_t>(std::lround(p.theta + dtheta_deg * 100.0)));
  return t;
}

// True when every sector has been read after `since`.
bool fresh(const PanTiltScan& s, std::uint64_t since) {
  for (std::uint64_t t : s.read_tick)
    if (t <= since) return false;
  return true;
}
}  // namespace

GateLogic::GateLogic(const GateSettings& s) : s_(s), go_(manoeuvre_settings(s)) {}

void GateLogic::start(std::uint64_t tick) {
  phase_ = Phase::settle;
  phase_tick_ = tick;
  state_ = ModeState::searching;
  reason_ = ModeReason::none;
  unlocked_since_ = 0;
  manoeuvres_ = 0;
  back_offs_ = 0;
  disagreements_ = 0;
  unsettled_ = 0;
  sighted_ = false;
  estimate_ = DoorEstimate{};
  go_.cancel();
}

void GateLogic::fail(ModeReason reason) {
  if (phase_ == Phase::idle) return;
  phase_ = Phase::idle;
  state_ = ModeState::failed;
  reason_ = reason;
  go_.cancel();
}

void GateLogic::stop() {
  phase_ = Phase::idle;
  if (state_ != ModeState::aligned && state_ != ModeState::failed) state_ = ModeState::off;
  go_.cancel();
}

GateOutput GateLogic::out(std::int32_t l, std::int32_t r) const {
  GateOutput o;
  o.left = l;
  o.right = r;
  o.request = phase_ != Phase::idle;
  o.state = state_;
  o.reason = reason_;
  o.width_mm = estimate_.ok ? static_cast<std::int32_t>(std::lround(estimate_.width_mm)) : 0;
  return o;
}

GateOutput GateLogic::step(const GateInputs& in) {
  if (phase_ == Phase::idle) return out(0, 0);
  if (in.scanner_failed) {
    fail(ModeReason::scanner);
    return out(0, 0);
  }
  switch (phase_) {
    case Phase::settle:
      if (in.tick - phase_tick_ >= s_.settle_ticks) {
        phase_ = Phase::scan;
        phase_tick_ = in.tick;
        scan_from_ = in.tick;
      }
      return out(0, 0);
    case Phase::scan:
      if (fresh(*in.scan, scan_from_)) {
        evaluate(in);
        if (phase_ != Phase::move) return out(0, 0);
        break;
      }
      if (in.tick - phase_tick_ > s_.scan_timeout_ticks) fail(ModeReason::scanner);
      return out(0, 0);
    default:
      break;
  }
  if (phase_ == Phase::back) {
    // Straight back until back_off_mm from where it began, or held again: then look again.
    const double dx = in.pose.x - back_from_.x, dy = in.pose.y - back_from_.y;
    if (std::hypot(dx, dy) >= 10.0 * s_.back_off_mm || stalled(in)) {
      enter(Phase::settle, in);
      state_ = ModeState::searching;
      return out(0, 0);
    }
    return out(-s_.speed_cm_s, -s_.speed_cm_s);
  }
  // Manoeuvring: one controller step from the current odometry.
  const executor::WheelSpeeds w = go_.step(executor::PostureUnits{in.pose.x, in.pose.y, in.pose.theta});
  if (!go_.active()) {
    enter(Phase::settle, in);
    state_ = ModeState::searching;
    return out(0, 0);
  }
  // Held where it stands (a protective stop the ring cannot lift from here: evidence in the
  // near field of the body, docs/DOORS.md §2): back off and look again from farther away.
  if (stalled(in)) {
    go_.cancel();
    ++back_offs_;
    back_from_ = in.pose;
    enter(Phase::back, in);
    return out(-s_.speed_cm_s, -s_.speed_cm_s);
  }
  return out(w.left, w.right);
}

void GateLogic::enter(Phase p, const GateInputs& in) {
  phase_ = p;
  phase_tick_ = in.tick;
  moved_pose_ = in.pose;
  moved_tick_ = in.tick;
}

bool GateLogic::stalled(const GateInputs& in) {
  const double dx = in.pose.x - moved_pose_.x, dy = in.pose.y - moved_pose_.y;
  const std::int64_t dth = executor::wrap_centideg(static_cast<std::int64_t>(in.pose.theta) - moved_pose_.theta);
  if (std::hypot(dx, dy) >= 50.0 || std::abs(dth) >= 50) {  // 5 mm, 0.5°
    moved_pose_ = in.pose;
    moved_tick_ = in.tick;
    return false;
  }
  return in.tick - moved_tick_ >= s_.stall_ticks;
}

// Why a staging pose rather than the seed's reactive turns: one scan from a standstill gives the
// passage's centre and direction to a few centimetres and a fraction of a degree; a manoeuvre
// to the centre line followed by a check from there converges in one or two rounds, where the
// seed's "distances to the corners agree within 300 mm" accepts half a metre off-centre at 1.5 m.
void GateLogic::evaluate(const GateInputs& in) {
  const PanTiltScan& scan = *in.scan;
  ptu::Echoes echoes;
  ptu::locate_echoes(scan, in.pose, in.tick, in.tick - scan_from_ + 1, s_.door.geometry, echoes);
  estimate_ = estimate_door(scan, echoes, s_.door);
  if (!estimate_.ok) {
    if (unlocked_since_ == 0) unlocked_since_ = in.tick;
    if (in.tick - unlocked_since_ > s_.timeout_ticks) {
      fail(ModeReason::no_passage);
      return;
    }
    phase_ = Phase::scan;  // look again (the seed waited, stopped, for a lock)
    phase_tick_ = in.tick;
    scan_from_ = in.tick;
    return;
  }
  // Acted on only when two scans in a row agree (in the odometry frame): one scan's spurious or
  // lost echoes can move an edge by half a metre (issue #19), two scans rarely the same way.
  const executor::PostureUnits now = compose(in.pose, estimate_.center_x, estimate_.center_y, estimate_.normal_deg);
  const bool before = sighted_;
  const double apart_mm = 0.1 * std::hypot(now.x - sighting_.x, now.y - sighting_.y);
  const double turn_deg = 0.01 * executor::wrap_centideg(static_cast<std::int64_t>(now.theta) - sighting_.theta);
  sighted_ = true;
  sighting_ = now;
  if (!before || apart_mm > s_.agree_mm || std::abs(turn_deg) > s_.agree_deg) {
    if (before) ++disagreements_;
    if (++unsettled_ > s_.max_looks) {
      fail(ModeReason::no_passage);
      return;
    }
    phase_ = Phase::scan;
    phase_tick_ = in.tick;
    scan_from_ = in.tick;
    return;
  }
  unlocked_since_ = 0;
  unsettled_ = 0;
  const DoorEstimate& d = estimate_;
  const double nx = std::cos(d.normal_deg * robot::kDeg), ny = std::sin(d.normal_deg * robot::kDeg);
  // The axle (origin) against the centre line through the passage's centre along the normal.
  lateral_mm_ = -(-d.center_x * ny + d.center_y * nx);  // + when the axle is left of the line
  heading_deg_ = -d.normal_deg;                         // + when the robot points left of the passage
  front_mm_ = d.center_x * nx + d.center_y * ny - s_.axle_to_front_mm;
  const bool lined_up = std::abs(lateral_mm_) <= s_.lateral_tolerance_mm && std::abs(heading_deg_) <= s_.heading_tolerance_deg;
  const bool close = d.lock.right_value <= s_.min_mm || d.lock.left_value <= s_.min_mm;  // seed "I'm close!"
  if ((lined_up && front_mm_ <= s_.stage_mm + s_.distance_tolerance_mm) || close) {
    phase_ = Phase::idle;
    state_ = ModeState::aligned;
    return;
  }
  if (manoeuvres_ >= s_.max_manoeuvres) {
    fail(ModeReason::cannot_align);
    return;
  }
  ++manoeuvres_;
  // The staging pose: on the centre line, stage_mm (front face) before the passage, facing it.
  const double back = s_.stage_mm + s_.axle_to_front_mm;
  go_.start(compose(in.pose, d.center_x - back * nx, d.center_y - back * ny, d.normal_deg));
  enter(Phase::move, in);
  state_ = ModeState::moving;
}

}  // namespace robuter::gate

// SPDX-License-Identifier: GPL-3.0-or-later
// The link's requests, each mapped onto the topic that carries it to its owner module, with
// the refusals that protect the robot (a latched emergency, a pose out of range); docs/PROTOCOL.md.
#include "modules/serial/link_port.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>

#include "kernel/kernel.hpp"
#include "modules/emergency/motion_gate.hpp"
#include "modules/localise/map_frame.hpp"
#include "modules/planner/map_bounds.hpp"
#include "protocol/codec/limits.hpp"

namespace robuter {

using protocol::PortResult;

LinkPort::LinkPort(Blackboard& bb, LinkWriters& w, const LinkSettings& settings)
    : w_(w),
      posture_(bb.posture.reader()),
      ranges_(bb.ranges.reader()),
      timing_(bb.us_timing.reader()),
      emergency_(bb.emergency.reader()),
      planner_status_(bb.planner_status.reader()),
      planner_map_(bb.planner_map.reader()),
      pan_tilt_scan_(bb.pan_tilt_scan.reader()),
      pan_tilt_status_(bb.pan_tilt_status.reader()),
      gate_status_(bb.gate_status.reader()),
      doors_status_(bb.doors_status.reader()),
      demo_status_(bb.demo_status.reader()),
      localisation_(bb.localisation.reader()),
      s_(settings),
      command_(bb.motion_command.reader()) {}

// An owner without a row in this run's table (`modules.enabled`) is never waited for.
void LinkPort::attach(Kernel& k) {
  kernel_ = &k;
  emergency_runs_ = executor_runs_ = localise_runs_ = false;
  for (std::size_t i = 0; i < k.process_count(); ++i) {
    emergency_runs_ = emergency_runs_ || (emergency_process_ && k.row(i).process == emergency_process_);
    executor_runs_ = executor_runs_ || (executor_process_ && k.row(i).process == executor_process_);
    localise_runs_ = localise_runs_ || (localise_process_ && k.row(i).process == localise_process_);
  }
}

void LinkPort::act(OperatorAction a) {
  const std::uint64_t t = tick();
  w_.events.modify([&](OperatorEvents& e) {
    e.ring[e.count % OperatorEvents::kCapacity] = OperatorEvent{a, t};
    ++e.count;
  });
  wake_emergency();
}

std::uint64_t LinkPort::tick() const { return kernel_ ? kernel_->tick() : 0; }

bool LinkPort::latched() const { return !emergency::admits_motion(emergency_.peek()); }

// AM: a request to the emergency module's gate, never to the motors.
PortResult LinkPort::request_motion(std::int32_t left, std::int32_t right) noexcept {
  const auto limit = static_cast<std::int32_t>(s_.max_speed_cm_s);
  if (std::abs(left) > limit || std::abs(right) > limit) return PortResult::out_of_range;
  if (latched() && (left != 0 || right != 0)) return PortResult::refused_emergency;
  w_.motion.publish(MotionRequest{left, right, tick()});
  act(OperatorAction::motion);
  return PortResult::ok;
}

PortResult LinkPort::set_servo(bool on) noexcept {
  if (on && latched()) return PortResult::refused_emergency;
  w_.servo.publish(ServoRequest{on});
  act(OperatorAction::servo);
  await_owners(true);  // the executor switches the servo: BO after the ack reads it
  return PortResult::ok;
}

// AY: refused unless configured, and then only for an allow-listed prefix. This robot's
// drives have no text controller behind them, so even an allowed line is not forwarded.
PortResult LinkPort::pass_through(std::string_view line) noexcept {
  if (!s_.permissions.pass_through) return PortResult::not_permitted;
  const bool allowed = std::any_of(s_.permissions.pass_through_allow.begin(), s_.permissions.pass_through_allow.end(),
                                   [&](const std::string& p) { return line.substr(0, p.size()) == p; });
  return allowed ? PortResult::unavailable : PortResult::not_permitted;
}

PortResult LinkPort::set_odometry(const protocol::Posture& p) noexcept {
  if (!protocol::heading_in_range(p.theta)) return PortResult::out_of_range;
  w_.odometry.publish(OdometrySet{p.x, p.y, p.theta});
  await_owners(true);  // the executor sets the odometry: BO after the ack reads it
  return PortResult::ok;
}

// AW: the target is a map pose; the executor drives in the odometry frame, so it is given the
// odometry posture the map pose has now (the same while no localisation runs).
PortResult LinkPort::go_to(const protocol::Posture& t) noexcept {
  if (!protocol::heading_in_range(t.theta)) return PortResult::out_of_range;
  if (latched()) return PortResult::refused_emergency;
  const executor::PostureUnits o = localise::odometry_posture({t.x, t.y, t.theta}, localisation_.peek(), posture_.peek().odometry_seq);
  w_.go_to.publish(GoToRequest{o.x, o.y, o.theta, true});
  act(OperatorAction::go_to);
  return PortResult::ok;
}

PortResult LinkPort::request_shutdown() noexcept {
  if (!s_.permissions.shutdown) return PortResult::not_permitted;
  shutdown_ = true;
  return PortResult::ok;
}

PortResult LinkPort::set_pan_tilt(bool on) noexcept {
  if (!pan_tilt_status_.advertised()) return PortResult::unavailable;
  if (on && !has_pan_tilt_unit()) return PortResult::no_unit;
  w_.modes.publish(ModeRequest{on});
  return PortResult::ok;
}

// The one rule of a mode the arbiter starts and ends: its module absent, unavailable; starting it
// needs the pan-tilt unit when the mode scans, and no latched emergency; ending it always goes.
PortResult LinkPort::switch_mode(bool present, bool scans, bool on, OperatorAction start, OperatorAction stop) noexcept {
  if (!present) return PortResult::unavailable;
  if (on && scans && !has_pan_tilt_unit()) return PortResult::no_unit;
  if (on && latched()) return PortResult::refused_emergency;
  act(on ? start : stop);
  return PortResult::ok;
}

PortResult LinkPort::set_gate_finder(bool on) noexcept {
  return switch_mode(gate_status_.advertised(), true, on, OperatorAction::start_gate, OperatorAction::stop_gate);
}

PortResult LinkPort::set_door_crossing(bool on) noexcept {
  return switch_mode(doors_status_.advertised(), true, on, OperatorAction::start_doors, OperatorAction::stop_doors);
}

// XT1 / XT0: the demonstration course, started and stopped like the other modes (no scanner).
PortResult LinkPort::set_demo(bool on) noexcept {
  return switch_mode(demo_status_.advertised(), false, on, OperatorAction::start_demo, OperatorAction::stop_demo);
}

PortResult LinkPort::set_sensor_table(const protocol::SensorTable& active) noexcept {
  w_.us.modify([&](UltrasonicSettings& s) { s.user_table = static_cast<std::uint32_t>(active.to_ulong()); });
  return PortResult::ok;
}

PortResult LinkPort::set_node_delay(std::int32_t ticks) noexcept {
  if (ticks < 0 || ticks > 1000) return PortResult::out_of_range;
  w_.us.modify([&](UltrasonicSettings& s) { s.node_delay_ticks = static_cast<std::uint32_t>(ticks); });
  return PortResult::ok;
}

PortResult LinkPort::set_us_timeout(std::int32_t ms) noexcept {
  if (ms < 1 || ms > 1000) return PortResult::out_of_range;
  w_.us.modify([&](UltrasonicSettings& s) { s.timeout_ms = static_cast<std::uint32_t>(ms); });
  return PortResult::ok;
}

PortResult LinkPort::set_auto_toggle(bool on) noexcept {
  w_.us.modify([&](UltrasonicSettings& s) { s.auto_toggle = on; });
  return PortResult::ok;
}

void LinkPort::message_received() noexcept {
  const std::uint64_t t = tick();
  w_.status.modify([&](LinkStatus& s) { s.last_message_tick = t; });
}

void LinkPort::immediate_stop() noexcept {
  w_.status.modify([](LinkStatus& s) { ++s.stop_seq; });
  act(OperatorAction::stop_byte);
}

// XR: clears a latched emergency whose cause is gone (the emergency module does it this tick);
// refused while the cause is still there.
PortResult LinkPort::reenable() noexcept {
  const EmergencyState& e = emergency_.peek();
  if (!e.latched) return PortResult::ok;
  if (!e.clearable) return PortResult::refused_emergency;
  w_.status.modify([](LinkStatus& s) { ++s.reenable_seq; });
  wake_emergency();
  return PortResult::ok;
}

// XG: checked here so that a refused goal changes nothing: the planner must run, the goal must
// lie on its map or the map must be able to move to hold the robot and the goal
// (planner::goal_acceptable, the planner's own rule), and no emergency may be latched (as AW).
PortResult LinkPort::set_goal(const protocol::Posture& g, bool with_theta) noexcept {
  if (!planner_running()) return PortResult::unavailable;
  if (with_theta && !protocol::heading_in_range(g.theta)) return PortResult::out_of_range;
  const planner::MapWindow now =
      planner_status_.advertised()
          ? planner::window_at(s_.planner, planner_status_.peek().map_x0_mm, planner_status_.peek().map_y0_mm)
          : planner::configured_window(s_.planner);
  const executor::PostureUnits at = map_pose();
  if (!planner::goal_acceptable(s_.planner, s_.model, now, at.x, at.y, g.x, g.y)) return PortResult::out_of_range;
  if (latched()) return PortResult::refused_emergency;
  w_.goal.modify([&](PlannerGoal& p) {
    p.x = g.x;
    p.y = g.y;
    p.theta = with_theta ? g.theta : 0;
    p.has_theta = with_theta;
    p.active = true;
    p.vias = 0;
    p.place = 0;
  });
  act(OperatorAction::start_planner);
  return PortResult::ok;
}

// XH: always accepted while the planner runs (a halt is never refused).
PortResult LinkPort::cancel_goal() noexcept {
  if (!planner_running()) return PortResult::unavailable;
  w_.goal.modify([](PlannerGoal& p) { p.active = false; });
  act(OperatorAction::halt);
  return PortResult::ok;
}

// XQ: the route from the robot's place (its odometry position) to place `number`, as the
// planner's goal with the route's via points (exploring: RouteTable::explore_points); checked
// here so that a refusal changes nothing: the place exists, the robot is in a place, a route
// joins them (and fits the goal's points), the planner's window can hold each of its legs
// (planner::goal_acceptable, leg by leg), no emergency is latched (as XG).
PortResult LinkPort::go_to_place(std::int32_t number, bool explore) noexcept {
  if (places_ == nullptr || routes_ == nullptr || !planner_running()) return PortResult::unavailable;
  if (number < 1 || static_cast<std::size_t>(number) > places_->places().size()) return PortResult::out_of_range;
  const executor::PostureUnits at = map_pose();
  const auto here = places_->place_at(places::Vec2(at.x * 1e-4, at.y * 1e-4));
  const std::size_t to = static_cast<std::size_t>(number - 1);
  if (!here || !routes_->found(*here, to)) return PortResult::out_of_range;
  static_assert(places::RouteTable::kMaxPoints <= PlannerGoal::kMaxVias + 1, "a route's points fit the goal");
  std::array<places::ViaPoint, places::RouteTable::kMaxPoints> buffer{};  // on the link's stack: no allocation
  const std::span<const places::ViaPoint> pts =
      explore ? std::span<const places::ViaPoint>(buffer.data(), routes_->explore_points(*here, to, buffer))
              : routes_->points(*here, to);
  if (pts.empty()) return PortResult::out_of_range;  // exploring: more points than a goal holds
  const planner::MapWindow now =
      planner_status_.advertised()
          ? planner::window_at(s_.planner, planner_status_.peek().map_x0_mm, planner_status_.peek().map_y0_mm)
          : planner::configured_window(s_.planner);
  std::int64_t fx = at.x, fy = at.y;
  for (const places::ViaPoint& p : pts) {
    if (!planner::goal_acceptable(s_.planner, s_.model, now, fx, fy, p.x, p.y)) return PortResult::out_of_range;
    fx = p.x;
    fy = p.y;
  }
  if (latched()) return PortResult::refused_emergency;
  w_.goal.modify([&](PlannerGoal& g) {
    g.x = pts.back().x;
    g.y = pts.back().y;
    g.theta = 0;
    g.has_theta = false;
    g.active = true;
    g.vias = static_cast<std::uint8_t>(pts.size() - 1);
    g.place = static_cast<std::uint16_t>(number);
    for (std::size_t k = 0; k + 1 < pts.size(); ++k)
      g.via[k] = {pts[k].x, pts[k].y, pts[k].theta, pts[k].has_theta, pts[k].spin};
  });
  act(OperatorAction::start_planner);
  return PortResult::ok;
}

// XA: the localisation takes the pose (or starts a global search) at its next activation.
PortResult LinkPort::set_map_pose(const protocol::Posture& pose, bool global) noexcept {
  if (!localisation_.advertised()) return PortResult::unavailable;
  if (!global && !protocol::heading_in_range(pose.theta)) return PortResult::out_of_range;
  w_.localise.publish(LocaliseRequest{global, pose.x, pose.y, pose.theta});
  await_owners(false);  // XW after the ack reads the new pose
  return PortResult::ok;
}

}  // namespace robuter

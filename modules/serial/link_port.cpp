// SPDX-License-Identifier: GPL-3.0-or-later
// Each protocol request mapped onto the topic that carries it; reads from the owners' topics.
#include "modules/serial/link_port.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>

#include "kernel/kernel.hpp"
#include "modules/emergency/motion_gate.hpp"
#include "modules/localise/map_frame.hpp"
#include "modules/planner/map_bounds.hpp"

namespace robuter {

using protocol::PortResult;

LinkPort::LinkPort(Blackboard& bb, const LinkWriters& w, const Config& cfg)
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
      cfg_(cfg),
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

// Generations only grow; the owners publish on every run (state, posture), so "changed since
// the start of the wait" is "ran since". The executor must also have applied the emergency
// module's latest command (which it triggers the executor for): with the default priorities it
// runs right after the emergency module, but a refused trigger or another table may delay it.
// The executor is run for the wait only when the request is its own (AS, AC): an extra posture
// sample changes nothing else, but the emergency module's at-rest test compares postures of
// different ticks, so it is not asked for without need.
bool LinkPort::waiting() {
  if (!waiting_) return false;
  if (emergency_ran() && executor_done() && localise_done()) {
    waiting_ = false;
    return false;
  }
  trigger_owners();
  return true;
}

bool LinkPort::emergency_ran() const { return !emergency_runs_ || emergency_.generation() != wait_emergency_gen_; }

bool LinkPort::executor_done() const {
  if (!executor_runs_) return true;
  if (wait_executor_ && posture_.generation() == wait_posture_gen_) return false;
  return posture_.peek().command_seq == command_.peek().seq;
}

bool LinkPort::localise_done() const {
  if (!localise_runs_) return true;
  const Localisation& l = localisation_.peek();
  return l.odometry_seq == w_.odometry.current().seq && l.request_seq == w_.localise.current().seq;
}

// The owners must run after the latest request: a new one restarts the wait from now.
void LinkPort::await_owners(bool executor) {
  if (!waiting_) wait_executor_ = false;
  waiting_ = true;
  wait_executor_ = wait_executor_ || executor;
  wait_emergency_gen_ = emergency_.generation();
  wait_posture_gen_ = posture_.generation();
  trigger_owners();
}

void LinkPort::trigger_owners() const {
  if (!kernel_) return;
  if (!emergency_ran()) kernel_->trigger(emergency_process_);
  if (executor_runs_ && !executor_done()) kernel_->trigger(executor_process_);
  if (localise_runs_ && !localise_done()) kernel_->trigger(localise_process_);
}

bool LinkPort::revive_link() {
  const std::uint64_t t = tick(), last = w_.status.current().last_message_tick;
  if (!(t > last && t - last > cfg_.emergency.comm_limit_ticks)) return false;
  message_received();
  await_owners(false);
  return true;
}

void LinkPort::wake_emergency() { await_owners(false); }

void LinkPort::act(OperatorAction a) {
  const std::uint64_t t = tick();
  w_.events.modify([&](OperatorEvents& e) {
    e.ring[e.count % OperatorEvents::kCapacity] = OperatorEvent{a, t};
    ++e.count;
  });
  wake_emergency();
}

std::uint64_t LinkPort::tick() const { return kernel_ ? kernel_->tick() : 0; }

bool LinkPort::latched() const { return !safety::admits_motion(emergency_.peek()); }

protocol::Ticks LinkPort::clock() const noexcept { return static_cast<protocol::Ticks>(tick()); }

// BO, BV and the stream: the odometry, as the seed reports it, unless [localise] report_corrected.
protocol::Posture LinkPort::posture() const noexcept {
  const Posture& p = posture_.peek();
  if (cfg_.localise.report_corrected) {
    const motion::PostureUnits m = map_pose();
    return {m.x, m.y, m.theta};
  }
  return {p.x, p.y, p.theta};
}

motion::PostureUnits LinkPort::map_pose() const { return localise::map_posture(posture_.peek(), localisation_.peek()); }

bool LinkPort::servo_on() const noexcept { return posture_.peek().servo; }

protocol::WheelSpeeds LinkPort::wheel_speeds() const noexcept {
  return {posture_.peek().left, posture_.peek().right};
}

void LinkPort::ranges(protocol::Ranges& out) const noexcept {
  const auto& mm = ranges_.peek().mm;
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = mm[i];
}

std::int32_t LinkPort::us_timeout() const noexcept { return static_cast<std::int32_t>(w_.us.current().timeout_ms); }

// The pan-tilt module's 72 sectors (zeros before the first sweep); unavailable when the module
// is not running (a module publishes its status at start-up).
PortResult LinkPort::pan_tilt(protocol::SectorKind kind, protocol::Sectors& out) const noexcept {
  if (pan_tilt_status_.generation() == 0) return PortResult::unavailable;
  const PanTiltScan& s = pan_tilt_scan_.peek();
  const auto& src = kind == protocol::SectorKind::raw        ? s.raw
                    : kind == protocol::SectorKind::filtered ? s.filtered
                                                             : s.differences;
  static_assert(kPanTiltSectors == protocol::kSectorCount, "BP/BF/BD sector count");
  std::copy(src.begin(), src.end(), out.begin());
  return PortResult::ok;
}

std::int32_t LinkPort::node_delay() const noexcept {
  return static_cast<std::int32_t>(w_.us.current().node_delay_ticks);
}
std::int32_t LinkPort::mean_node_time() const noexcept {
  return static_cast<std::int32_t>(timing_.peek().mean_node_ticks);
}
std::int32_t LinkPort::mean_scan_time() const noexcept {
  return static_cast<std::int32_t>(timing_.peek().mean_scan_ticks);
}

// AM: a request to the emergency module's gate, never to the motors.
PortResult LinkPort::request_motion(std::int32_t left, std::int32_t right) noexcept {
  const auto limit = static_cast<std::int32_t>(cfg_.robot.max_speed_cm_s);
  if (std::abs(left) > limit || std::abs(right) > limit) return PortResult::out_of_range;
  if (latched() && (left != 0 || right != 0)) return PortResult::refused_emergency;
  const std::uint64_t t = tick();
  w_.motion.modify([&](MotionRequest& m) {
    m.left = left;
    m.right = right;
    ++m.seq;
    m.tick = t;
  });
  act(OperatorAction::motion);
  return PortResult::ok;
}

PortResult LinkPort::set_servo(bool on) noexcept {
  if (on && latched()) return PortResult::refused_emergency;
  w_.servo.modify([&](ServoRequest& s) {
    s.on = on;
    ++s.seq;
  });
  act(OperatorAction::servo);
  await_owners(true);  // the executor switches the servo: BO after the ack reads it
  return PortResult::ok;
}

// AY: refused unless configured, and then only for an allow-listed prefix. This robot's
// drives have no text controller behind them, so even an allowed line is not forwarded.
PortResult LinkPort::pass_through(std::string_view line) noexcept {
  if (!cfg_.permissions.pass_through) return PortResult::not_permitted;
  const bool allowed = std::any_of(cfg_.permissions.pass_through_allow.begin(), cfg_.permissions.pass_through_allow.end(),
                                   [&](const std::string& p) { return line.substr(0, p.size()) == p; });
  return allowed ? PortResult::unavailable : PortResult::not_permitted;
}

PortResult LinkPort::set_odometry(const protocol::Posture& p) noexcept {
  if (p.theta <= -18000 || p.theta > 18000) return PortResult::out_of_range;
  w_.odometry.modify([&](OdometrySet& o) {
    o.x = p.x;
    o.y = p.y;
    o.theta = p.theta;
    ++o.seq;
  });
  await_owners(true);  // the executor sets the odometry: BO after the ack reads it
  return PortResult::ok;
}

// AW: the target is a map pose; the executor drives in the odometry frame, so it is given the
// odometry posture the map pose has now (the same while no localisation runs).
PortResult LinkPort::go_to(const protocol::Posture& t) noexcept {
  if (t.theta <= -18000 || t.theta > 18000) return PortResult::out_of_range;
  if (latched()) return PortResult::refused_emergency;
  const motion::PostureUnits o = localise::odometry_posture({t.x, t.y, t.theta}, localisation_.peek(), posture_.peek().odometry_seq);
  w_.go_to.modify([&](GoToRequest& g) {
    g.x = o.x;
    g.y = o.y;
    g.theta = o.theta;
    g.active = true;
    ++g.seq;
  });
  act(OperatorAction::go_to);
  return PortResult::ok;
}

PortResult LinkPort::request_shutdown() noexcept {
  if (!cfg_.permissions.shutdown) return PortResult::not_permitted;
  shutdown_ = true;
  return PortResult::ok;
}

// Why refuse Ap, AG, Ad without a unit instead of acking and failing later: the operator
// learns at once that nothing will scan (XD would only say so afterwards). Off is always ack.
bool LinkPort::has_pan_tilt_unit() const {
  return pan_tilt_status_.generation() > 0 && pan_tilt_scan_.peek().fitted;
}

PortResult LinkPort::set_pan_tilt(bool on) noexcept {
  if (pan_tilt_status_.generation() == 0) return PortResult::unavailable;
  if (on && !has_pan_tilt_unit()) return PortResult::no_unit;
  w_.modes.modify([&](ModeRequest& m) {
    m.pan_tilt = on;
    ++m.seq;
    ++m.pan_tilt_seq;
  });
  return PortResult::ok;
}

PortResult LinkPort::set_gate_finder(bool on) noexcept {
  if (gate_status_.generation() == 0) return PortResult::unavailable;
  if (on && !has_pan_tilt_unit()) return PortResult::no_unit;
  if (on && latched()) return PortResult::refused_emergency;
  w_.modes.modify([&](ModeRequest& m) {
    m.gate = on;
    ++m.seq;
    ++m.gate_seq;
  });
  act(on ? OperatorAction::start_gate : OperatorAction::stop_gate);
  return PortResult::ok;
}

PortResult LinkPort::set_door_crossing(bool on) noexcept {
  if (doors_status_.generation() == 0) return PortResult::unavailable;
  if (on && !has_pan_tilt_unit()) return PortResult::no_unit;
  if (on && latched()) return PortResult::refused_emergency;
  w_.modes.modify([&](ModeRequest& m) {
    m.doors = on;
    ++m.seq;
    ++m.doors_seq;
  });
  act(on ? OperatorAction::start_doors : OperatorAction::stop_doors);
  return PortResult::ok;
}

// XT1 / XT0: the demonstration course, started and stopped like the other modes.
PortResult LinkPort::set_demo(bool on) noexcept {
  if (demo_status_.generation() == 0) return PortResult::unavailable;
  if (on && latched()) return PortResult::refused_emergency;
  act(on ? OperatorAction::start_demo : OperatorAction::stop_demo);
  return PortResult::ok;
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

protocol::EmergencyStatus LinkPort::emergency() const noexcept {
  const EmergencyState& e = emergency_.peek();
  protocol::EmergencyStatus s;
  s.held = e.held;
  s.latched = e.latched;
  s.enabled = e.enabled;
  s.cause = e.cause;
  s.granted_pct = e.granted_pct;
  s.envelope = e.envelope;
  s.protective = e.protective;
  return s;
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

protocol::KernelFigures LinkPort::kernel_figures() const noexcept {
  protocol::KernelFigures f;
  if (!kernel_) return f;
  const std::size_t n = std::min(kernel_->process_count(), figures_.size());
  for (std::size_t i = 0; i < n; ++i) {
    const ProcessStats& s = kernel_->stats(i);
    figures_[i] = {kernel_->row(i).name, s.activations, s.overruns, s.slips, s.mean_ns() / 1000, s.max_ns / 1000};
  }
  f.ticks = kernel_->tick();
  f.max_late_us = static_cast<std::int64_t>(kernel_->lateness().max_us());
  f.p99_late_us = static_cast<std::int64_t>(kernel_->lateness().quantile_us(0.99));
  f.processes = std::span<const protocol::ProcessFigures>(figures_.data(), n);
  return f;
}

std::string_view LinkPort::firmware_version() const noexcept { return ROBUTER_VERSION; }

std::uint32_t LinkPort::features() const noexcept {
  std::uint32_t f = protocol::kFeatureGoTo;
  if (cfg_.permissions.pass_through) f |= protocol::kFeaturePassThrough;
  if (planner_running()) f |= protocol::kFeaturePlanner;
  if (pan_tilt_status_.generation() > 0) f |= protocol::kFeaturePanTilt;
  if (gate_status_.generation() > 0) f |= protocol::kFeatureGate;
  if (doors_status_.generation() > 0) f |= protocol::kFeatureDoors;
  return f;
}

// XG: checked here so that a refused goal changes nothing: the planner must run, the goal must
// lie on its map or the map must be able to move to hold the robot and the goal
// (planner::goal_acceptable, the planner's own rule), and no emergency may be latched (as AW).
PortResult LinkPort::set_goal(const protocol::Posture& g, bool with_theta) noexcept {
  if (!planner_running()) return PortResult::unavailable;
  if (with_theta && (g.theta <= -18000 || g.theta > 18000)) return PortResult::out_of_range;
  const planner::MapWindow now =
      planner_status_.generation() > 0
          ? planner::window_at(cfg_.planner, planner_status_.peek().map_x0_mm, planner_status_.peek().map_y0_mm)
          : planner::configured_window(cfg_.planner);
  const motion::PostureUnits at = map_pose();
  if (!planner::goal_acceptable(cfg_, now, at.x, at.y, g.x, g.y)) return PortResult::out_of_range;
  if (latched()) return PortResult::refused_emergency;
  w_.goal.modify([&](PlannerGoal& p) {
    p.x = g.x;
    p.y = g.y;
    p.theta = with_theta ? g.theta : 0;
    p.has_theta = with_theta;
    p.active = true;
    p.vias = 0;
    p.place = 0;
    ++p.seq;
  });
  act(OperatorAction::start_planner);
  return PortResult::ok;
}

// XH: always accepted while the planner runs (a halt is never refused).
PortResult LinkPort::cancel_goal() noexcept {
  if (!planner_running()) return PortResult::unavailable;
  w_.goal.modify([](PlannerGoal& p) {
    p.active = false;
    ++p.seq;
  });
  act(OperatorAction::halt);
  return PortResult::ok;
}

PortResult LinkPort::planner_status(protocol::PlannerReport& out) const noexcept {
  if (!planner_running()) return PortResult::unavailable;
  const PlannerStatus& s = planner_status_.peek();
  out.state = s.state;
  out.goal_x = s.goal_x;
  out.goal_y = s.goal_y;
  out.path_mm = s.path_mm;
  out.prefix_mm = s.prefix_mm;
  out.replans = s.plans > 0 ? s.plans - 1 : 0;
  out.scans = s.scans;
  out.plan_us = s.plan_us;
  out.max_us = s.run_us_max;
  return PortResult::ok;
}

// Why: one place's report, numbers 1-based in the file's order; positions to 0.1 mm.
static void fill_place(const places::PlaceGraph& g, std::size_t i, protocol::PlaceReport& out) {
  const places::Place& p = g.places()[i];
  out.count = static_cast<std::int32_t>(g.places().size());
  out.number = static_cast<std::int32_t>(i + 1);
  out.name = p.name;
  out.centre_x = static_cast<std::int32_t>(std::lround(p.centre.x() * 1e4));
  out.centre_y = static_cast<std::int32_t>(std::lround(p.centre.y() * 1e4));
  const auto& doors = g.doors_of(i);
  out.neighbours = static_cast<std::int32_t>(doors.size());
  for (std::size_t k = 0; k < doors.size() && k < protocol::PlaceReport::kMaxNeighbours; ++k) {
    const places::Door& d = g.doors()[doors[k]];
    out.neighbour[k] = static_cast<std::int32_t>((d.a == i ? d.b : d.a) + 1);
  }
}

PortResult LinkPort::place_here(protocol::PlaceReport& out) const noexcept {
  if (places_ == nullptr) return PortResult::unavailable;
  const motion::PostureUnits p = map_pose();
  const auto at = places_->place_at(places::Vec2(p.x * 1e-4, p.y * 1e-4));
  if (!at) {
    out = protocol::PlaceReport{};
    out.count = static_cast<std::int32_t>(places_->places().size());
    return PortResult::ok;
  }
  fill_place(*places_, *at, out);
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
  const motion::PostureUnits at = map_pose();
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
      planner_status_.generation() > 0
          ? planner::window_at(cfg_.planner, planner_status_.peek().map_x0_mm, planner_status_.peek().map_y0_mm)
          : planner::configured_window(cfg_.planner);
  std::int64_t fx = at.x, fy = at.y;
  for (const places::ViaPoint& p : pts) {
    if (!planner::goal_acceptable(cfg_, now, fx, fy, p.x, p.y)) return PortResult::out_of_range;
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
    ++g.seq;
  });
  act(OperatorAction::start_planner);
  return PortResult::ok;
}

// XW: unavailable while no localisation runs (its topic never published).
PortResult LinkPort::localisation(protocol::LocaliseReport& out) const noexcept {
  if (localisation_.generation() == 0) return PortResult::unavailable;
  const Localisation& l = localisation_.peek();
  out.state = l.state;
  out.x = l.x;
  out.y = l.y;
  out.theta = l.theta;
  out.major_mm = l.major_mm;
  out.minor_mm = l.minor_mm;
  out.axis = l.axis;
  out.sigma_theta = l.sigma_theta;
  out.cluster_pct = l.cluster_pct;
  out.particles = l.particles;
  out.steps = l.steps;
  return PortResult::ok;
}

// XA: the localisation takes the pose (or starts a global search) at its next activation.
PortResult LinkPort::set_map_pose(const protocol::Posture& pose, bool global) noexcept {
  if (localisation_.generation() == 0) return PortResult::unavailable;
  if (!global && (pose.theta <= -18000 || pose.theta > 18000)) return PortResult::out_of_range;
  w_.localise.modify([&](LocaliseRequest& r) {
    r.global = global;
    r.x = pose.x;
    r.y = pose.y;
    r.theta = pose.theta;
    ++r.seq;
  });
  await_owners(false);  // XW after the ack reads the new pose
  return PortResult::ok;
}

PortResult LinkPort::place_info(std::int32_t number, protocol::PlaceReport& out) const noexcept {
  if (places_ == nullptr) return PortResult::unavailable;
  if (number < 1 || static_cast<std::size_t>(number) > places_->places().size()) return PortResult::out_of_range;
  fill_place(*places_, static_cast<std::size_t>(number - 1), out);
  return PortResult::ok;
}

// The window lives in the planner's topic: valid while the line is handled (one thread).
static_assert(PlannerMapWindow::kSide == protocol::kMapWindowSide, "XM window size");

PortResult LinkPort::planner_map(protocol::MapWindow& out) const noexcept {
  if (!planner_running() || planner_map_.peek().cell_mm == 0) return PortResult::unavailable;
  const PlannerMapWindow& w = planner_map_.peek();
  out.side = PlannerMapWindow::kSide;
  out.cell_mm = w.cell_mm;
  out.center_x = w.center_x;
  out.center_y = w.center_y;
  out.cells = std::string_view(w.cells.data(), w.cells.size());
  return PortResult::ok;
}

namespace {
// A mode module's report for XD: absent until the module publishes (it does at start-up).
protocol::ModeReport mode_report(const Reader<ModeStatus>& r) {
  if (r.generation() == 0) return {.absent = true};
  return {.state = r.peek().state, .reason = r.peek().reason};
}
}  // namespace

// XD: a module that is not running reads "absent"; unavailable only when none of them runs.
PortResult LinkPort::modes(protocol::ModesReport& out) const noexcept {
  if (pan_tilt_status_.generation() == 0 && gate_status_.generation() == 0 && doors_status_.generation() == 0 &&
      demo_status_.generation() == 0)
    return PortResult::unavailable;
  out.pan_tilt = mode_report(pan_tilt_status_);
  out.gate = mode_report(gate_status_);
  out.doors = mode_report(doors_status_);
  out.sweeps = pan_tilt_scan_.peek().sweeps;
  out.width_mm = gate_status_.peek().width_mm;
  out.crossing_ticks = doors_status_.peek().duration_ticks;
  out.demo.absent = demo_status_.generation() == 0;
  if (!out.demo.absent) {
    const DemoStatus& d = demo_status_.peek();
    out.demo.state = d.state;
    out.demo.reason = d.reason;
    out.demo_phase = d.phase;
    out.demo_laps = d.laps;
  }
  return PortResult::ok;
}

}  // namespace robuter

// SPDX-License-Identifier: GPL-3.0-or-later
// The link's reports: what the replies read from the owners' topics (BO, BU, XE, XP, XD, …).
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

protocol::Ticks LinkPort::clock() const noexcept { return static_cast<protocol::Ticks>(tick()); }

// BO, BV and the stream: the odometry, as the seed reports it, unless [localise] report_corrected.
protocol::Posture LinkPort::posture() const noexcept {
  const Posture& p = posture_.peek();
  if (s_.report_corrected) {
    const executor::PostureUnits m = map_pose();
    return {m.x, m.y, m.theta};
  }
  return {p.x, p.y, p.theta};
}

executor::PostureUnits LinkPort::map_pose() const { return localise::map_posture(posture_.peek(), localisation_.peek()); }

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
  if (!pan_tilt_status_.advertised()) return PortResult::unavailable;
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

// Why refuse Ap, AG, Ad without a unit instead of acking and failing later: the operator
// learns at once that nothing will scan (XD would only say so afterwards). Off is always ack.
bool LinkPort::has_pan_tilt_unit() const {
  return pan_tilt_status_.advertised() && pan_tilt_scan_.peek().fitted;
}

protocol::EmergencyStatus LinkPort::emergency() const noexcept {
  const EmergencyState& e = emergency_.peek();
  return {.held = e.held, .latched = e.latched, .cause = e.cause, .enabled = e.enabled,
          .granted_pct = e.granted_pct, .envelope = e.envelope, .protective = e.protective};
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
  if (s_.permissions.pass_through) f |= protocol::kFeaturePassThrough;
  if (planner_running()) f |= protocol::kFeaturePlanner;
  if (pan_tilt_status_.advertised()) f |= protocol::kFeaturePanTilt;
  if (gate_status_.advertised()) f |= protocol::kFeatureGate;
  if (doors_status_.advertised()) f |= protocol::kFeatureDoors;
  return f;
}

PortResult LinkPort::planner_status(protocol::PlannerReport& out) const noexcept {
  if (!planner_running()) return PortResult::unavailable;
  const PlannerStatus& s = planner_status_.peek();
  out = {.state = s.state, .goal_x = s.goal_x, .goal_y = s.goal_y, .path_mm = s.path_mm,
         .prefix_mm = s.prefix_mm, .replans = s.plans > 0 ? s.plans - 1 : 0, .scans = s.scans,
         .plan_us = s.plan_us, .max_us = s.run_us_max};
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
  const executor::PostureUnits p = map_pose();
  const auto at = places_->place_at(places::Vec2(p.x * 1e-4, p.y * 1e-4));
  if (!at) {
    out = protocol::PlaceReport{};
    out.count = static_cast<std::int32_t>(places_->places().size());
    return PortResult::ok;
  }
  fill_place(*places_, *at, out);
  return PortResult::ok;
}

// XW: unavailable while no localisation runs (its topic never published).
PortResult LinkPort::localisation(protocol::LocaliseReport& out) const noexcept {
  if (!localisation_.advertised()) return PortResult::unavailable;
  const Localisation& l = localisation_.peek();
  out = {.state = l.state, .x = l.x, .y = l.y, .theta = l.theta, .major_mm = l.major_mm, .minor_mm = l.minor_mm,
         .axis = l.axis, .sigma_theta = l.sigma_theta, .cluster_pct = l.cluster_pct, .particles = l.particles,
         .steps = l.steps};
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
  out = {.side = PlannerMapWindow::kSide, .cell_mm = w.cell_mm, .center_x = w.center_x, .center_y = w.center_y,
         .cells = std::string_view(w.cells.data(), w.cells.size())};
  return PortResult::ok;
}

namespace {
// A mode module's report for XD: absent until the module publishes (it does at start-up).
protocol::ModeReport mode_report(const Reader<ModeStatus>& r) {
  if (!r.advertised()) return {.absent = true};
  return {.state = r.peek().state, .reason = r.peek().reason};
}
}  // namespace

// XD: a module that is not running reads "absent"; unavailable only when none of them runs.
PortResult LinkPort::modes(protocol::ModesReport& out) const noexcept {
  if (!pan_tilt_status_.advertised() && !gate_status_.advertised() && !doors_status_.advertised() &&
      !demo_status_.advertised())
    return PortResult::unavailable;
  out.pan_tilt = mode_report(pan_tilt_status_);
  out.gate = mode_report(gate_status_);
  out.doors = mode_report(doors_status_);
  out.sweeps = pan_tilt_scan_.peek().sweeps;
  out.width_mm = gate_status_.peek().width_mm;
  out.crossing_ticks = doors_status_.peek().duration_ticks;
  out.demo.absent = !demo_status_.advertised();
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

// SPDX-License-Identifier: GPL-3.0-or-later
// Planner process glue: ring → map, goal requests, the scan / plan / follow loop, reports.
#include "modules/planner/planner_module.hpp"

#include <algorithm>
#include <time.h>

#include <cmath>

#include "kernel/cpu_time.hpp"
#include "kernel/kernel.hpp"
#include "kernel/log.hpp"
#include "modules/localise/map_frame.hpp"
#include "modules/planner/map_bounds.hpp"
#include "modules/planner/map_window.hpp"
#include "modules/planner/sonar_mapping.hpp"

namespace robuter {

namespace {
constexpr double kTenthMm = 1e-4;                  // m per 0.1 mm
constexpr double kCentideg = plan::kPi / 18000.0;  // rad per 0.01°
constexpr std::uint64_t kScanTimeoutTicks = 600;   // a scan gives up waiting after this (6 s)
constexpr std::uint64_t kSettleTicks = 20;         // ticks after the drive reports zero speeds
// C-space layers rebuilt per activation after the window moved (65 for the default rectangle:
// 32 slices, 32 turn layers, the relaxation), so that no activation carries the whole rebuild.
constexpr int kRebuildLayersPerRun = 3;
// A motion paused this long by a protective stop is replanned (3 s: three times the envelope's
// clear time), and after this many such replans in a row the navigation ends `blocked`.
constexpr std::uint64_t kPausedReplanTicks = 300;
constexpr std::uint32_t kPausedReplansMax = 5;
// rad: the door crossing is lent the robot only this close to facing the door (20°, the door
// crossing bench's starting box: docs/DOORS.md).
constexpr double kCrossingHeadingError = 20.0 * plan::kPi / 180.0;

std::uint32_t to_mm(double m) { return m <= 0.0 ? 0u : static_cast<std::uint32_t>(std::lround(m * 1000.0)); }

planner::FollowerSettings follower_settings(const planner::PlannerSettings& s) {
  planner::FollowerSettings f;
  f.max_drive_cm_s = s.drive_cm_s;
  f.max_turn_cm_s = s.turn_cm_s;
  f.wheel_base_mm = s.wheel_base_mm;
  return f;
}
}  // namespace

PlannerModule::PlannerModule(Blackboard& bb, const PlannerModuleConfig& cfg, const robot::RobotModel& model,
                             const planner::PlannerNeighbours& neighbours)
    : ModeProcess(bb, MotionSource::planner, bb.planner_motion.writer(), bb.planner_status.writer(),
                  ModeRequests::Wake::new_speeds),
      s_(planner::make_settings(cfg, model, neighbours.pan_far_mm)),
      planner_(s_.planner),
      follower_(follower_settings(s_)),
      posture_(bb.posture.reader()),
      localisation_(bb.localisation.reader()),
      ranges_(bb.ranges.reader()),
      selection_(bb.sonar_selection.reader()),
      pan_tilt_(bb.pan_tilt_scan.reader()),
      goal_in_(bb.planner_goal.reader()),
      emergency_(bb.emergency.reader()),
      doors_status_(bb.doors_status.reader()),
      map_out_(bb.planner_map.writer()),
      map_x0_mm_(cfg.map_origin_x_mm),
      map_y0_mm_(cfg.map_origin_y_mm),
      cfg_(cfg),
      cross_doors_(neighbours.cross_doors) {}

// Everything sized here: the map, the C-space layers, the searches' arrays.
bool PlannerModule::init(Kernel& k) {
  kernel_ = &k;
  const bool prior = prior_.has_value();
  planner_.set_map(prior ? std::move(*prior_) : plan::OccupancyMap(s_.map, s_.hit_threshold, s_.initial_count));
  prior_.reset();
  if (pictures_) pictures_->reserve(planner_, kMaxPicturePath);
  goal_in_.copy();  // goals from before the start are not served
  for (int i = 0; i < robot::kRingSensors; ++i) read_tick_[i] = ranges_.peek().read_tick[i];
  pan_tick_ = pan_tilt_.peek().read_tick;
  log::info("planner: map {} x {} cells of {} mm, {} footprint, {}", s_.map.width, s_.map.height,
            std::lround(s_.map.resolution * 1000.0),
            s_.planner.footprint == plan::FootprintKind::Disc ? "disc" : "rectangle",
            prior ? "from the a-priori map file" : "unknown");
  const plan::Pose2 p = pose_now();
  publish_status(k.tick());
  publish_window(k.tick(), p);
  return true;
}

void PlannerModule::close(Kernel& k) {
  if (navigating(state_)) requests_.send(k, false, 0, 0);
}

// The robot's pose on its map: the goals, the places' walls and the a-priori map are there.
plan::Pose2 PlannerModule::pose_now() {
  const executor::PostureUnits p = localise::map_posture(posture_.peek(), localisation_.peek());
  const double theta = p.theta * kCentideg;
  if (!have_heading_) {
    heading_ = theta;
    have_heading_ = true;
  } else {
    heading_ += std::remainder(theta - last_theta_, 2.0 * plan::kPi);
  }
  last_theta_ = theta;
  return {p.x * kTenthMm, p.y * kTenthMm, heading_};
}

// At most one new reading per sensor per activation (a sensor is read every node cycle), so the
// work is bounded by 24 beams of beam_range and the body's cells.
void PlannerModule::integrate_ranges(const plan::Pose2& pose) {
  const UltrasonicRanges& r = ranges_.peek();
  plan::OccupancyMap& map = planner_.map();
  for (int i = 0; i < robot::kRingSensors; ++i) {
    if (r.read_tick[i] == read_tick_[i]) continue;
    read_tick_[i] = r.read_tick[i];
    ++fresh_[i];
    if (r.mm[i] == 0) continue;  // inactive or lost
    const bool no_echo = (r.no_echo >> i) & 1u;
    planner::integrate_reading(map, pose, s_.robot.ring.sensors[static_cast<std::size_t>(i)].mount, r.mm[i] / 1000.0, no_echo, s_.beam_range, s_.beam_half_angle);
  }
  integrate_pan_tilt();
  planner::mark_body_free(map, pose, s_.robot.body);
  // A door's opening stays open: the ring's echoes off its jambs fall in it (docs/PLACES.md).
  for (const plan::Point2& p : openings_) {
    const plan::Cell c = map.cell_of(p);
    if (map.contains(c) && map.state(c) == plan::CellState::Occupied) map.mark_free(c);
  }
}

// At most 72 beams per activation (one per sector; the unit fires a sector every 30 ms or so,
// so a few in practice). A sector cleared by Ag (tick 0) or without a range is skipped.
void PlannerModule::integrate_pan_tilt() {
  const PanTiltScan& scan = pan_tilt_.peek();
  plan::OccupancyMap& map = planner_.map();
  for (std::size_t i = 0; i < scan.read_tick.size(); ++i) {
    if (scan.read_tick[i] == pan_tick_[i]) continue;
    pan_tick_[i] = scan.read_tick[i];
    if (scan.read_tick[i] == 0 || scan.raw[i] <= 0) continue;
    const SectorPose& at = scan.pose[i];
    const plan::Pose2 fired{at.x * kTenthMm, at.y * kTenthMm, at.theta * kCentideg};
    const planner::SensorMount mount =
        planner::pan_tilt_mount(s_.robot.pan_tilt, scan.direction[i] * kCentideg);
    const double range = scan.raw[i] / 1000.0;
    planner::integrate_reading(map, fired, mount, range, range >= s_.pan_far, s_.beam_range, s_.robot.pan_tilt.half_angle);
  }
}

void PlannerModule::skip_readings() {
  const UltrasonicRanges& r = ranges_.peek();
  for (int i = 0; i < robot::kRingSensors; ++i) read_tick_[i] = r.read_tick[i];
  pan_tick_ = pan_tilt_.peek().read_tick;
}

// The same rule as the link's check (planner::goal_acceptable), from the posture now: the robot
// may have moved a little since the XG was taken, which the margin absorbs.
void PlannerModule::place_window(std::uint64_t tick) {
  const planner::MapWindow now = planner::window_at(cfg_, map_x0_mm_, map_y0_mm_);
  const executor::PostureUnits at = localise::map_posture(posture_.peek(), localisation_.peek());
  const PlannerGoal::Via t = target();
  if (planner::on_window(now, t.x, t.y)) return;
  const auto shift = planner::window_shift(cfg_, s_.robot, now, at.x, at.y, t.x, t.y);
  if (!shift) return;  // the plan then reports the goal off the map: unreachable
  planner_.shift_map(shift->dx, shift->dy);
  map_x0_mm_ += std::int64_t{shift->dx} * cfg_.cell_mm;
  map_y0_mm_ += std::int64_t{shift->dy} * cfg_.cell_mm;
  prepared_seq_ = 0;  // the cost field is to be made on the moved map
  log::info("planner: map window moved by ({}, {}) cells to ({}, {}) mm at tick {}", shift->dx, shift->dy,
            map_x0_mm_, map_y0_mm_, tick);
}

void PlannerModule::rebuild_step(std::uint64_t tick) {
  if (!planner_.rebuild_step(kRebuildLayersPerRun)) return;
  fresh_.fill(0);  // the scan's readings count from now, marked on the rebuilt layers
  if (settled_) scan_tick_ = tick;
}

void PlannerModule::finish(PlannerState state, bool stop) {
  const bool was = navigating(state_);
  follower_.cancel();
  planner_.cancel_steps();  // a field or a search under way is moot; the layers sync again
  if (stop && was) requests_.send(*kernel_, false, 0, 0);
  if (state != state_) log::info("planner: {} (plans {}, scans {})", word(state), plans_, scans_);
  state_ = state;
}

// A run handed by the arbiter (XG) starts the newest goal; an XH outside a run still reads
// `cancelled` afterwards.
void PlannerModule::serve_goal(std::uint64_t tick) {
  if (!begun()) {
    if (goal_in_.updated() && !goal_in_.copy().active && state_ != PlannerState::idle)
      finish(PlannerState::cancelled, navigating(state_));
    return;
  }
  const PlannerGoal& g = goal_ = goal_in_.copy();
  goal_number_ = goal_in_.generation();
  plans_ = scans_ = 0;
  via_next_ = 0;
  paused_replans_ = 0;
  paused_since_ = 0;
  path_m_ = prefix_m_ = 0.0;
  prefix_len_ = leg_count_ = 0;
  final_turn_ = false;
  if (g.vias > 0) log::info("planner: goal place {} at {} {} through {} route points", g.place, g.x, g.y, g.vias);
  else log::info("planner: goal {} {}{}", g.x, g.y, g.has_theta ? " with heading" : "");
  begin_scan(tick);
  place_window(tick);
}

// The arbiter's word (modules/emergency): XH cancels; the operator's command or an emergency stops.
bool PlannerModule::interrupted() {
  if (!navigating(state_)) return false;
  const ModeReason why = claim_.ended();
  if (why == ModeReason::none) return false;
  if (why == ModeReason::cancelled) {
    finish(PlannerState::cancelled, false);
    return true;
  }
  const bool emergency = why == ModeReason::emergency;
  log::info("planner: navigation ended by {}", emergency ? "an emergency" : "the operator");
  finish(emergency ? PlannerState::stopped : PlannerState::operator_ended, false);
  return true;
}

void PlannerModule::stop_here() {
  follower_.cancel();
  planner_.cancel_steps();
  request(0, 0);
}

void PlannerModule::begin_scan(std::uint64_t tick) {
  stop_here();
  state_ = PlannerState::scanning;
  settled_ = false;
  step_waited_ = false;
  scan_tick_ = tick;
  ++scans_;
}

// The first readings after the stop may come from the last centimetres of motion: harmless.
bool PlannerModule::scan_done(std::uint64_t tick) {
  const Posture& p = posture_.peek();
  if (!settled_) {
    if (p.left == 0 && p.right == 0 && tick >= scan_tick_ + kSettleTicks) {
      settled_ = true;
      scan_tick_ = tick;
      fresh_.fill(0);
    } else if (tick < scan_tick_ + kScanTimeoutTicks) {
      return false;
    }
  }
  const std::uint32_t active = selection_.peek().active;
  bool all = active != 0;
  for (int i = 0; i < robot::kRingSensors; ++i)
    if ((active >> i) & 1u) all = all && fresh_[i] >= s_.scan_passes;
  if (all) return true;
  if (tick >= scan_tick_ + kScanTimeoutTicks) {
    log::warn("planner: the ring gave no full scan in {} ticks; planning with what is known", kScanTimeoutTicks);
    return true;
  }
  return false;
}

bool PlannerModule::add_final_turn(const plan::Pose2& pose) {
  if (!goal_.has_theta) return false;
  return add_turn(pose, goal_.theta);
}

// A via point with a heading (the point before a narrow door): turn to face the door there.
bool PlannerModule::add_via_turn(const plan::Pose2& pose) {
  if (!at_via() || !goal_.via[via_next_].has_theta) return false;
  return add_turn(pose, goal_.via[via_next_].theta);
}

bool PlannerModule::add_turn(const plan::Pose2& pose, std::int32_t theta) {
  return add_turn_to(pose, pose.heading + std::remainder(theta * kCentideg - pose.heading, 2.0 * plan::kPi));
}

bool PlannerModule::add_turn_to(const plan::Pose2& pose, double target) {
  if (final_turn_) return false;
  final_turn_ = true;
  if (s_.planner.footprint == plan::FootprintKind::Rectangle) {
    // The turn measured from where the robot stands: the body keeps the turn clearance at
    // every heading it sweeps.
    if (!planner_.can_turn_at(pose, target)) {
      log::info("planner: no room to turn to the heading asked");
      return false;
    }
  }
  legs_[0] = planner::Leg{{pose.x, pose.y}, target, true, false, 0};
  leg_count_ = 1;
  follower_.start({legs_.data(), 1});
  return true;
}

// A route's point passed (or passed over): stop, scan and plan to the next one, the window
// following it.
void PlannerModule::next_via(std::uint64_t tick, const char* why) {
  log::info("planner: route point {} of {} {}", via_next_ + 1, goal_.vias, why);
  ++via_next_;
  final_turn_ = false;  // the next point's (or the goal's) turn is still to come
  prepared_seq_ = 0;  // the next point's cost field is to be made
  begin_scan(tick);
  place_window(tick);
}

bool PlannerModule::via_reached(std::uint64_t tick, const plan::Pose2& pose) {
  if (goal_.via[via_next_].spin) {  // exploring: a full turn at the place's centre, then the scan
    if (add_turn_to(pose, pose.heading + 2.0 * plan::kPi)) return true;
    next_via(tick, "turned round at the place's centre: scanning it");
    return false;
  }
  if (add_via_turn(pose)) return true;
  const PlannerGoal::Via& v = goal_.via[via_next_];
  if (!cross_doors_ || !v.has_theta) {
    next_via(tick, "reached");
    return false;
  }
  // The crossing starts only facing the door: where the turn had no room, the robot may face
  // away from it (seen: corridor-b-4, 2.1 m wide, the door behind the robot).
  if (std::abs(std::remainder(v.theta * kCentideg - pose.heading, 2.0 * plan::kPi)) > kCrossingHeadingError) {
    log::warn("planner: route point {} of {}: not facing the door (no room to turn); the route ends", via_next_ + 1,
              goal_.vias);
    finish(PlannerState::blocked, true);
    return false;
  }
  begin_crossing(tick);
  return false;
}

void PlannerModule::begin_crossing(std::uint64_t tick) {
  stop_here();
  state_ = PlannerState::crossing;
  ++door_wish_;
  lent_seen_ = false;
  crossing_since_ = tick;
  log::info("planner: route point {} of {} reached, facing the door: the door crossing takes the robot",
            via_next_ + 1, goal_.vias);
}

void PlannerModule::crossing_step(std::uint64_t tick, const plan::Pose2& pose) {
  if (claim_.lent()) {
    lent_seen_ = true;
    return;
  }
  if (!lent_seen_) {  // the arbiter has not lent the robot yet (it does within a tick or two)
    if (tick < crossing_since_ + kLendTicks) return;
    log::warn("planner: the door crossing did not take the robot in {} ticks; the route ends", kLendTicks);
    return finish(PlannerState::blocked, true);
  }
  const ModeStatus& d = doors_status_.peek();
  if (d.state != ModeState::crossed) {
    log::info("planner: the door crossing ended {} ({}); the route ends", word(d.state), word(d.reason));
    return finish(PlannerState::blocked, true);
  }
  // Crossed, by the crossing's own end test: the robot must be in the place beyond the door (the
  // place of the point after it), else the crossing stopped short or turned away (seen: "crossed"
  // 0.8 m before room-12's door, facing 40° off it) and the route ends here.
  if (place_graph_ != nullptr && via_next_ + 1 < goal_.vias) {
    const PlannerGoal::Via& after = goal_.via[via_next_ + 1];
    const auto beyond = place_graph_->place_at(places::Vec2(after.x * 1e-4, after.y * 1e-4));
    const auto here = place_graph_->place_at(places::Vec2(pose.x, pose.y));
    if (beyond && here != beyond) {
      log::warn("planner: the door crossing ended crossed outside {}; the route ends",
                place_graph_->places()[*beyond].name);
      return finish(PlannerState::blocked, true);
    }
  }
  // Crossed: on to the point after the door (0.9 m past it, straight ahead: the crossing stops
  // about 0.5 m past it, where turning towards the room's centre met the jambs — room-02 ended
  // `blocked` so); scan and plan to it.
  next_via(tick, "crossed by the door crossing");
}

void PlannerModule::plan_step(std::uint64_t tick, const plan::Pose2& pose) {
  const plan::Point2 goal = target_point();
  if (at_via() && std::hypot(goal.x - pose.x, goal.y - pose.y) <= via_tolerance()) {
    if (via_reached(tick, pose)) {
      state_ = PlannerState::moving;
      final_prefix_ = true;
    }
    return;
  }
  if (std::hypot(goal.x - pose.x, goal.y - pose.y) <= s_.goal_tolerance) {
    if (add_final_turn(pose)) {
      state_ = PlannerState::moving;
      final_prefix_ = true;
      return;
    }
    return finish(PlannerState::reached, true);
  }
  const std::int64_t t0 = thread_cpu_us();
  auto elapsed_us = [&] { return static_cast<std::uint32_t>(std::max<std::int64_t>(0, thread_cpu_us() - t0)); };
  const bool searching = planner_.searching();  // a search under way continues; its grids hold still
  // A sync that freed cells (~1 ms each), or a picture, is this activation's work: the field's
  // or the search's step waits for the next (once: then it goes on whatever that sync folded).
  if (!searching && costly_now_ && !step_waited_) {
    step_waited_ = true;
    return;
  }
  step_waited_ = false;
  if (!searching && (prepared_seq_ != goal_number_ || !planner_.field_ready(goal))) {
    // A new goal, or a field a sync dropped (a cell made cheaper: sonar misses do it nearly every
    // scan): the cost field (a Dijkstra over the whole map) in steps of at most
    // PlannerSettings::field_cells_per_run cells, one per activation, and the search in the next, so that no
    // activation carries a whole field or a field and a search (docs/PLANNER.md, "The module").
    // Made inside the search's first step instead, the field took 5-8 ms there (the seed 000 lab run).
    if (planner_.prepare_step(goal, s_.field_cells_per_run)) prepared_seq_ = goal_number_;
    return;
  }
  // The search in steps of at most PlannerSettings::search_pops_per_run states, one per activation.
  if (!planner_.stepping()) plan_us_ = 0;
  plan::PlanResult r;
  const bool ended = planner_.plan_step(pose, goal, s_.search_pops_per_run, r);
  plan_us_ += elapsed_us();
  if (!ended) return;
  ++plans_;
  switch (r.status) {
    case plan::PlanStatus::Found: break;
    case plan::PlanStatus::StartBlocked:
      picture(tick, r, pose, goal);
      return finish(PlannerState::blocked, true);
    case plan::PlanStatus::StartOutside:
      picture(tick, r, pose, goal);
      return finish(PlannerState::outside, true);
    default:
      if (r.status == plan::PlanStatus::SearchLimit)  // reported as unreachable; the log says why
        log::warn("planner: plan {}: no path: search memory exhausted ({} states expanded)", plans_,
                  r.expanded);
      if (at_via()) {  // a route's helper point: on to the next one (the goal itself ends it)
        picture(tick, r, pose, goal);
        return next_via(tick, "unreachable, passed over");
      }
      path_m_ = prefix_m_ = 0.0;
      prefix_len_ = leg_count_ = 0;
      picture(tick, r, pose, goal);
      return finish(PlannerState::unreachable, true);
  }
  const auto& path = planner_.waypoints();
  path_m_ = planner::chain_length(path);
  std::size_t n = planner::visible_prefix(planner_.map(), path, {pose.x, pose.y}, s_.follow_range);
  n = std::min(n, prefix_.size());
  std::copy_n(path.begin(), n, prefix_.begin());
  std::size_t used = 0;
  const int slices = s_.planner.footprint == plan::FootprintKind::Rectangle ? planner_.slices() : 0;
  leg_count_ = planner::build_legs({prefix_.data(), n}, pose.heading, slices, legs_, used);
  prefix_len_ = used;
  final_prefix_ = used == path.size();
  prefix_m_ = planner::chain_length({prefix_.data(), prefix_len_});
  picture(tick, r, pose, goal);
  log::info("planner: plan {}: path {:.2f} m, following {:.2f} m in {} legs, {} us, {} states", plans_, path_m_,
            prefix_m_, leg_count_, plan_us_, r.expanded);
  if (leg_count_ == 0) {  // the path is the robot's own cell: as close as the grid allows
    if (add_final_turn(pose)) {
      state_ = PlannerState::moving;
      return;
    }
    return finish(PlannerState::reached, true);
  }
  follower_.start({legs_.data(), leg_count_});
  state_ = PlannerState::moving;
  // A new path to the point: its arrival turn is to be made again. The map pose may move during
  // a turn in place (the localisation's correction): the robot then turned at a point it no
  // longer is at, drives there again and must face the door there (seen: room-16's door, 13 cm
  // moved during the turn, then "not facing the door").
  final_turn_ = false;
}

void PlannerModule::move_step(std::uint64_t tick, const plan::Pose2& pose) {
  // Our motion paused by a protective stop (obstacle evidence in the envelope; it resumes by
  // itself once clear): if it stays paused, the evidence is not going away — stop, scan (the
  // ring's readings go into the map as they do for any obstacle) and plan again; after
  // kPausedReplansMax such replans with no prefix driven in between, give up: `blocked`.
  const bool paused = emergency_.peek().protective && (requests_.left() != 0 || requests_.right() != 0);
  if (!paused) {
    paused_since_ = 0;
  } else if (paused_since_ == 0) {
    paused_since_ = tick;
  } else if (tick - paused_since_ >= kPausedReplanTicks) {
    paused_since_ = 0;
    if (++paused_replans_ > kPausedReplansMax) {
      log::warn("planner: the envelope kept stopping the robot ({} replans): giving up", kPausedReplansMax);
      return finish(PlannerState::blocked, true);
    }
    log::info("planner: motion paused by obstacle evidence for {} s, stopping to scan and replan",
              kPausedReplanTicks / 100);
    return begin_scan(tick);
  }
  // New obstacles on what is left to drive (or where a turn is to happen): stop, scan, replan.
  // A turn in place under way is finished first, so that the robot stops at a heading the
  // search can start from (a slice that carries moves), not half-way between two.
  if (const planner::Leg* leg = follower_.current(); leg != nullptr && leg->drive) {
    if (!follower_.turning() && planner::prefix_blocked(planner_, {prefix_.data(), prefix_len_}, leg->first)) {
      log::info("planner: obstacle on the path, stopping to scan");
      return begin_scan(tick);
    }
  }
  const planner::Wheels w = follower_.step(pose);
  if (follower_.active()) return request(w.left, w.right);
  const plan::Point2 goal = target_point();
  if (final_prefix_ && at_via() && std::hypot(goal.x - pose.x, goal.y - pose.y) <= via_tolerance()) {
    if (via_reached(tick, pose)) request(0, 0);
    return;
  }
  if (final_prefix_ && std::hypot(goal.x - pose.x, goal.y - pose.y) <= s_.goal_tolerance) {
    if (add_final_turn(pose)) return request(0, 0);
    return finish(PlannerState::reached, true);
  }
  paused_replans_ = 0;  // a whole prefix driven: progress
  begin_scan(tick);
}

void PlannerModule::sync_map() {
  if (planner_.sync() > 0) costly_now_ = true;
}

void PlannerModule::keep_place_grid(const plan::Pose2& pose) {
  if (place_graph_ == nullptr || place_grids_ == nullptr) return;
  const std::optional<std::size_t> at = place_graph_->place_at(places::Vec2(pose.x, pose.y));
  if (!at) return;  // between places (off the graph): no node to save
  places::PlaceGridSlot* slot = place_grids_->try_fill();
  if (slot == nullptr) return;  // the writer still holds the last one: dropped and counted
  slot->place = *at;
  const bool cut = places::cut_place_into(*place_graph_, *at, planner_.map(), plan::Point2{pose.x, pose.y}, slot->grid);
  place_grids_->publish(cut);
}

void PlannerModule::run(Kernel& k) {
  const std::int64_t t0 = thread_cpu_us();
  const std::uint64_t tick = k.tick();
  const plan::Pose2 pose = pose_now();
  costly_now_ = false;
  // The last activation's plan, pictured before anything changes the map or the layers.
  take_picture();
  // After a window move the layers are rebuilt a few per activation (the robot is stopped, the
  // state reads scanning); the map takes no readings until they match it again.
  if (planner_.rebuilding()) rebuild_step(tick);
  if (planner_.rebuilding()) {
    skip_readings();
  } else {
    integrate_ranges(pose);
    // Into the layers at once, in every state (the planner defers it itself while a search or a
    // field is in steps): one activation's readings, never the ~6,000 cells a door crossing or an
    // idle robot would pile up (folded in one sync after a crossing: 4.3-5.2 ms).
    sync_map();
  }
  if (!interrupted()) {
    serve_goal(tick);
    if (state_ == PlannerState::scanning && !planner_.rebuilding()) {
      if (scan_done(tick)) {
        state_ = PlannerState::planning;
        keep_place_grid(pose);
      }
    }
    const bool planned = state_ == PlannerState::planning;
    if (planned) plan_step(tick, pose);
    else if (state_ == PlannerState::moving) move_step(tick, pose);
    else if (state_ == PlannerState::crossing) crossing_step(tick, pose);
    // While the robot drives and scans, the kept tree for the plan's goal grows, a step per
    // activation, so that a replan after new obstacles searches only where it broke
    // (docs/PLANNER.md, "The kept tree") — not in the activation that planned: a search step and
    // a tree step together took up to 16 ms (the seed 000 lab run) — nor in one whose syncs freed
    // cells or that took a picture (with a tree step, up to 6.7 ms there).
    if (!planned && !costly_now_ && (state_ == PlannerState::moving || state_ == PlannerState::scanning) &&
        planner_.tree_growing() && planner_.grow_tree_step(s_.tree_pops_per_run))
      log::info("planner: plan {}: kept tree {}: {} states", plans_, planner_.tree_kept() ? "made" : "not kept",
                planner_.tree_states());
  } else {
    serve_goal(tick);  // a new goal in the same tick as the interruption still starts
  }
  run_us_max_ = std::max(run_us_max_, static_cast<std::uint32_t>(std::max<std::int64_t>(0, thread_cpu_us() - t0)));
  publish_status(tick);
  publish_window(tick, pose);
}

// The plan's outcome noted; the copy (one pass over the map's cells and the layers: 2.5-4.6 ms
// for 320 x 320 cells and 32 slices) is take_picture()'s, at the next activation's start.
void PlannerModule::picture(std::uint64_t tick, const plan::PlanResult& r, const plan::Pose2& pose, plan::Point2 goal) {
  if (pictures_ == nullptr) return;
  shot_ = Shot{true, r, pose, goal, tick, plans_, goal_number_, prefix_len_};
}

void PlannerModule::take_picture() {
  if (!shot_.due) return;
  shot_.due = false;
  costly_now_ = true;
  plan::PlanSnapshot* snap = pictures_->try_fill();
  if (snap == nullptr) {  // the writer still draws the previous picture: this plan's is dropped, and said so
    log::warn("planner: picture of plan {} for goal {} dropped (the writer is still drawing; {} dropped so far)",
              shot_.plan, shot_.goal_seq, pictures_->dropped());
    return;
  }
  if (snap->capture(planner_, shot_.result, shot_.pose, shot_.goal)) {
    snap->prefix_len = std::min(shot_.prefix_len, snap->path_len);
    snap->goal_seq = shot_.goal_seq;
    snap->plan_number = shot_.plan;
    snap->tick = shot_.tick;
  }
  pictures_->publish();
}

void PlannerModule::publish_status(std::uint64_t tick) {
  PlannerStatus s;
  s.state = state_;
  s.goal_x = goal_.x;
  s.goal_y = goal_.y;
  s.path_mm = to_mm(path_m_);
  s.prefix_mm = to_mm(prefix_m_);
  s.plans = plans_;
  s.scans = scans_;
  s.plan_us = plan_us_;
  s.run_us_max = run_us_max_;
  s.goal_seq = goal_number_;
  s.vias = goal_.vias;
  s.via_next = via_next_;
  s.goal_place = goal_.place;
  s.door_wish = door_wish_;
  s.map_x0_mm = static_cast<std::int32_t>(map_x0_mm_);
  s.map_y0_mm = static_cast<std::int32_t>(map_y0_mm_);
  s.tick = tick;
  status_out_.publish(s);
}

void PlannerModule::publish_window(std::uint64_t tick, const plan::Pose2& pose) {
  const plan::OccupancyMap& map = planner_.map();
  const plan::Cell c = map.cell_of({pose.x, pose.y});
  const plan::Point2 centre = map.center(c);
  map_out_.modify([&](PlannerMapWindow& w) {
    planner::render_window(map, c, PlannerMapWindow::kSide, w.cells);
    w.center_x = static_cast<std::int32_t>(std::lround(centre.x / kTenthMm));
    w.center_y = static_cast<std::int32_t>(std::lround(centre.y / kTenthMm));
    w.cell_mm = static_cast<std::int32_t>(std::lround(map.resolution() * 1000.0));
    w.tick = tick;
  });
}

}  // namespace robuter

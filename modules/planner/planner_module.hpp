// SPDX-License-Identifier: GPL-3.0-or-later
// The grid planner as a kernel process: map from the ring, plan, follow the visible prefix, scan, replan.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>

#include "modules/emergency/mode_process.hpp"
#include "modules/planner/lib/planner.hpp"
#include "modules/planner/path_follower.hpp"
#include "modules/planner/picture_mailbox.hpp"
#include "modules/places/place_grid_mailbox.hpp"
#include "modules/planner/planner_settings.hpp"
#include "modules/planner/route.hpp"
#include "modules/topics.hpp"

namespace robuter {

// Why: the states of a navigation under way (the planner holds, or has lent, the robot): the one
// rule for "still going" (the module's interruptions, the tests' runs).
constexpr bool navigating(PlannerState s) {
  return s == PlannerState::scanning || s == PlannerState::planning || s == PlannerState::moving ||
         s == PlannerState::crossing;
}

// Seed 000's loop on the Robuter: with a goal (XG), stop and scan with the ring, mark the map
// (seed 003's hit counts), plan (rectangle with heading slices by default, seed 004), follow the
// part of the path within sonar range and in sight, stop, scan, replan, until the goal is
// reached or shown unreachable. It moves the robot only through its own motion requests, which
// the emergency module arbitrates like any other source: a mode as gate, doors and demo are
// (ModeProcess: the arbiter's runs, the requests and their final zero, the status).
class PlannerModule final : public ModeProcess<PlannerStatus> {
 public:
  static constexpr std::size_t kMaxPrefix = 512;  // waypoints of the followed prefix kept
  static constexpr std::size_t kMaxPicturePath = 8192;  // waypoints of a plan kept for its picture
  static constexpr double kViaTolerance = 0.30;  // m: a route's via point is passed this close
  static constexpr std::uint64_t kLendTicks = 50;  // ticks the arbiter has to lend the robot to the door crossing

  // Its own section, the robot model, and what it reads of the pan-tilt's and the places' sections.
  PlannerModule(Blackboard& bb, const PlannerModuleConfig& cfg, const robot::RobotModel& model,
                const planner::PlannerNeighbours& neighbours);
  // Pictures (robuterd --planner-pictures): every plan is copied into `box` in the activation
  // that made it, for a writer outside the kernel. Set before init(), which sizes the copy.
  void set_pictures(planner::PictureMailbox* box) { pictures_ = box; }
  // Place grids ([places] grids_dir): at the end of each scan in a place of `graph`, that place's
  // grid is cut from the map into `box` for the writer (seed 003's drawsec(); no allocation).
  void set_place_grids(const places::PlaceGraph* graph, places::PlaceGridMailbox* box) {
    place_graph_ = graph;
    place_grids_ = box;
  }
  // The place graph ([places] file): a door crossing on a route must end in the place beyond the
  // door (seed 003's localisation by point-in-polygon). Must outlive the module.
  void set_places(const places::PlaceGraph* graph) { place_graph_ = graph; }
  // The a-priori map ([planner] map_file, planner/prior_map.hpp), of the configured geometry:
  // init() starts from it instead of an unknown map. Set before init().
  void set_prior_map(plan::OccupancyMap map) { prior_ = std::move(map); }
  // Known structure the moving window takes (a place graph's walls: places/wall_raster.hpp),
  // at init (set_map) and after each move. It must outlive the module. Set before init().
  void set_structure(const plan::OccupancyMap* structure) { planner_.set_structure(structure); }
  // Cells remembered from an earlier run (saved place grids, [places] load_grids), taken after
  // the structure (plan::Planner::set_memory). Same conditions.
  void set_memory(const plan::OccupancyMap* memory) { planner_.set_memory(memory); }
  // Cells kept free whatever the ring says (a place graph's door openings, m, odometry frame:
  // places/wall_raster.hpp), re-freed after each activation's readings. Must outlive the module.
  void set_openings(std::span<const plan::Point2> cells) { openings_ = cells; }

  // Sizes the planner for the configured map (the only allocation) and publishes "idle".
  bool init(Kernel& k) override;
  void run(Kernel& k) override;
  // Asks the gate for zero speeds when navigating.
  void close(Kernel& k) override;

  // For tests and pictures, outside the periodic path.
  const plan::Planner& planner() const { return planner_; }
  std::span<const plan::Waypoint> prefix() const { return {prefix_.data(), prefix_len_}; }
  const planner::PlannerSettings& settings() const { return s_; }
  PlannerState state() const { return state_; }
  // The map window's lower-left corner, odometry frame, mm (moves for a goal off the map).
  std::int64_t map_x0_mm() const { return map_x0_mm_; }
  std::int64_t map_y0_mm() const { return map_y0_mm_; }

 private:
  // Marks every new ring and pan-tilt reading along its beam, and the body's cells free.
  void integrate_ranges(const plan::Pose2& pose);
  // Marks every new pan-tilt reading along its beam, from the posture it was fired at.
  void integrate_pan_tilt();
  // While the layers are rebuilt after a window move: the readings are passed over, unmarked.
  void skip_readings();
  // A goal off the map: moves the window to hold the robot and the goal, if they fit.
  void place_window(std::uint64_t tick);
  // One step of the layers' rebuild after a move; when it ends, the scan counts from now.
  void rebuild_step(std::uint64_t tick);
  // A new XG (start) or XH (cancel).
  void serve_goal(std::uint64_t tick);
  // True (and the navigation ended) when the arbiter took the robot back: XH, the operator, an emergency.
  bool interrupted();
  // Stops where it is: no path followed, no plan under way, a zero request.
  void stop_here();
  // Enters the scanning state: stop and wait for fresh readings.
  void begin_scan(std::uint64_t tick);
  // Scanning: done once every firing sensor was read scan_passes times after the robot stopped.
  bool scan_done(std::uint64_t tick);
  // Plans from here, takes the visible prefix, starts following it (or ends the navigation).
  void plan_step(std::uint64_t tick, const plan::Pose2& pose);
  // A route (XQ): the point being driven to, a via point before the goal or the goal itself.
  PlannerGoal::Via target() const { return at_via() ? goal_.via[via_next_] : PlannerGoal::Via{goal_.x, goal_.y}; }
  plan::Point2 target_point() const { const PlannerGoal::Via t = target(); return {t.x * 1e-4, t.y * 1e-4}; }
  bool at_via() const { return via_next_ < goal_.vias; }
  // m: a via point counts as passed this close (looser than the goal's: only a way point).
  double via_tolerance() const { return std::max(s_.goal_tolerance, kViaTolerance); }
  void next_via(std::uint64_t tick, const char* why);
  // At a via point: its turn first (true: the turn started; exploring, a full circle at a place's
  // centre), then, at the point before a narrow door with [places] cross_doors, the door
  // crossing, else the next point (after a scan: the place's grid is kept then).
  bool via_reached(std::uint64_t tick, const plan::Pose2& pose);
  // At the point before a narrow door, turned to face it ([places] cross_doors): ask the arbiter
  // to lend the robot to the door crossing, and wait (docs/PLACES.md "Doors on a route").
  void begin_crossing(std::uint64_t tick);
  // Crossing: while lent, wait; given back, go on after the door (crossed) or end (failed).
  void crossing_step(std::uint64_t tick, const plan::Pose2& pose);
  bool add_via_turn(const plan::Pose2& pose);
  // Adds a turn in place to `theta` (0.01 degree) when free and not yet added for this point.
  bool add_turn(const plan::Pose2& pose, std::int32_t theta);
  // The same to the unwrapped heading `target` (rad; a full circle for an exploration's scan).
  bool add_turn_to(const plan::Pose2& pose, double target);
  // Folds the map's new readings into the layers; a sync that freed cells (its costly part) makes
  // the activation costly_now_: no search or tree step then (docs/PLANNER.md "Real time").
  void sync_map();
  // One control step; a new obstacle on the prefix or its end leads to a scan.
  void move_step(std::uint64_t tick, const plan::Pose2& pose);
  // Adds a turn in place to the goal's heading when asked and the turn is free; true if added.
  bool add_final_turn(const plan::Pose2& pose);
  // Ends the navigation in `state`; `stop` sends the run's final zero request.
  void finish(PlannerState state, bool stop);
  // Sends this run's wheel-speed request (cm/s) to the arbiter.
  void request(std::int32_t left, std::int32_t right) { requests_.send(*kernel_, true, left, right); }
  // Cuts the grid of the place the robot scanned in into the place grid mailbox, if kept.
  void keep_place_grid(const plan::Pose2& pose);
  // Notes the plan just made for a picture, if pictures are on: take_picture() copies it into
  // the mailbox at the start of the next activation (no allocation; the copy, a pass over the map
  // and every layer, took 2.5-4.6 ms in the seed 000 lab run: an activation's work of its own).
  void picture(std::uint64_t tick, const plan::PlanResult& r, const plan::Pose2& pose, plan::Point2 goal);
  void take_picture();
  void publish_status(std::uint64_t tick);
  void publish_window(std::uint64_t tick, const plan::Pose2& pose);
  // The odometry posture in m and rad, the heading unwrapped (continuous across ±π).
  plan::Pose2 pose_now();

  planner::PlannerSettings s_;
  std::optional<plan::OccupancyMap> prior_;  // the a-priori map until init() hands it to the planner
  plan::Planner planner_;
  planner::PathFollower follower_;
  Reader<Posture> posture_;
  Reader<Localisation> localisation_;  // the map frame's correction (modules/localise/map_frame.hpp)
  Reader<UltrasonicRanges> ranges_;
  Reader<SonarSelection> selection_;
  Reader<PanTiltScan> pan_tilt_;         // the pan-tilt's sectors: more beams for the map
  Reader<PlannerGoal> goal_in_;
  Reader<EmergencyState> emergency_;     // a protective stop pausing our motion (replan after a while)
  Reader<ModeStatus> doors_status_;      // how the door crossing we lent the robot to ended
  Writer<PlannerMapWindow> map_out_;
  std::span<const plan::Point2> openings_;  // cells kept free (door openings), m
  planner::PictureMailbox* pictures_ = nullptr;  // where plans go for pictures (null: off)
  const places::PlaceGraph* place_graph_ = nullptr;   // the place graph (null: none)
  places::PlaceGridMailbox* place_grids_ = nullptr;   // where their grids go for the writer
  Kernel* kernel_ = nullptr;               // the kernel running us (for the requests' triggers), set by init()

  PlannerState state_ = PlannerState::idle;
  PlannerGoal goal_{};                     // goal being served
  std::uint32_t goal_number_ = 0;          // its topic's generation: the goal's number (PlannerStatus.goal_seq)
  std::array<std::uint64_t, robot::kRingSensors> read_tick_{};  // last reading marked, per sensor
  std::array<std::uint32_t, robot::kRingSensors> fresh_{};      // readings since the scan's stop
  std::array<std::uint64_t, kPanTiltSectors> pan_tick_{};         // last pan-tilt reading marked, per sector
  std::array<plan::Waypoint, kMaxPrefix> prefix_{};               // the followed prefix
  std::size_t prefix_len_ = 0;
  std::array<planner::Leg, planner::PathFollower::kMaxLegs> legs_{};  // legs of the prefix
  std::size_t leg_count_ = 0;
  bool final_prefix_ = false;              // the prefix ends at the goal
  bool final_turn_ = false;                // the goal's heading turn was added
  bool settled_ = false;                   // scanning: the drive has stopped
  std::uint64_t scan_tick_ = 0;            // scanning: tick the stop was asked (then: settled)
  double heading_ = 0.0;                   // rad, unwrapped odometry heading
  double last_theta_ = 0.0;                // rad, wrapped heading of the previous activation
  bool have_heading_ = false;
  std::uint32_t plans_ = 0, scans_ = 0;    // for this goal
  std::uint8_t via_next_ = 0;              // the route's next via point (goal_.vias: the goal itself)
  std::uint32_t door_wish_ = 0;            // PlannerStatus.door_wish: bumped to ask for the crossing
  bool lent_seen_ = false;                 // crossing: the arbiter has lent the robot (it comes back when the crossing ends)
  std::uint64_t crossing_since_ = 0;       // crossing: tick the crossing was asked for
  std::uint64_t paused_since_ = 0;         // tick our motion was first seen paused by a protective stop (0: not)
  std::uint32_t paused_replans_ = 0;       // replans in a row after such pauses, with no prefix driven since
  std::uint32_t plan_us_ = 0;              // µs, thread CPU time: the last search (all its steps)
  std::uint32_t run_us_max_ = 0;           // µs, thread CPU time: the longest activation
  bool costly_now_ = false;                // this activation synced freed cells or took a picture
  // A plan noted for its picture (picture()), taken at the next activation's start.
  struct Shot {
    bool due = false;            // noted, not yet taken
    plan::PlanResult result{};   // the plan's outcome
    plan::Pose2 pose{};          // m, rad: where it was planned from
    plan::Point2 goal{};         // m: what it was planned to
    std::uint64_t tick = 0;      // kernel tick of the plan
    std::uint32_t plan = 0;      // the plan's number for its goal
    std::uint32_t goal_seq = 0;  // the goal's sequence number
    std::size_t prefix_len = 0;  // waypoints of the path followed
  };
  Shot shot_{};
  bool step_waited_ = false;               // the last activation put a search's first step off for a sync
  std::uint32_t prepared_seq_ = 0;         // goal number whose cost field was computed (0: none)
  double path_m_ = 0.0, prefix_m_ = 0.0;   // m
  std::int64_t map_x0_mm_ = 0, map_y0_mm_ = 0;   // mm, the map window's lower-left corner
  PlannerModuleConfig cfg_;                // its section, for the window's rule (planner::window_shift)
  bool cross_doors_ = false;               // places.cross_doors: lend the robot to the doors at a narrow door
};

}  // namespace robuter

// SPDX-License-Identifier: GPL-3.0-or-later
// The door crossing's decisions, pure: the seed's steering on echoes carried by odometry, the
// wait when blocked on both sides, the end test, and a last stretch so the rear clears the door.
#pragma once

#include <cstdint>

#include "modules/doors/min_read.hpp"
#include "modules/doors/steering.hpp"
#include "modules/emergency/mode_output.hpp"
#include "modules/ptu/echo_points.hpp"
#include "modules/ptu/scan_view.hpp"
#include "modules/topics.hpp"

namespace robuter::doors {

// Everything the crossing needs, in its own units (mm, ticks, cm/s).
struct CrossingSettings {
  BodyGeometry body = body_geometry(robot::kRobuter);  // robot and pan-tilt geometry, safety
  ptu::EchoGeometry echoes;                  // pan axis, faces, beam, echo grouping
  SteerSpeeds speeds;                        // forward 2, back 1 cm/s
  SideSectors sides;                         // left 1..17, right 54..70
  std::int32_t max_dist_mm = 1500;           // MAX_DIST
  std::uint32_t time_before_move_ticks = 500;  // TIME_BEFORE_MOVE
  std::int32_t entered_mm = 1500;            // both sides this close: inside the door
  double beside_mm = 300.0;                  // and each side's echo this close to abreast of the pan axis, mm
  double look_ahead_mm = 300.0;              // edges this far ahead of the front face measure the opening
  double spread_weight = 0.0;                // an echo is judged over this fraction of its uncertainty (0: at its bearing)
  double exit_mm = 400.0;                    // driven on once through
  std::uint64_t max_age_ticks = 600;         // older readings are ignored
  std::uint32_t timeout_ticks = 30000;       // the whole crossing, 0 = no limit
};

// One activation's view: the scan, odometry, the pan-tilt's state.
using CrossingInputs = ptu::ScanInputs;

// One activation's decision: the wish (speeds, state: starting, crossing, waiting, leaving,
// crossed, failed) and how long the crossing has taken.
struct CrossingOutput : ModeOutput {
  std::uint32_t duration_ticks = 0;  // since the start
};

// What the echoes say this activation (for tests and the log).
struct CrossingView {
  SideThreats threats;                       // too close on either side (or ahead: both)
  bool entered = false;                      // both sides close: inside the door
  bool clear = false;                        // the seed's end test holds
  double opening_mm = 0.0;                   // the opening just ahead: nearest edge left + right of the centre line, mm (0: not both seen)
  bool too_narrow = false;                   // that opening is narrower than the body and its safety margins
};

class DoorCrossing {
 public:
  explicit DoorCrossing(const CrossingSettings& s);
  // Ad (or the passage finder's hand-over): wait for a fresh scan of the front half, then cross.
  void start(std::uint64_t tick);
  void fail(ModeReason reason);
  CrossingOutput step(const CrossingInputs& in);
  bool active() const { return state_ == ModeState::starting || state_ == ModeState::crossing ||
                               state_ == ModeState::waiting || state_ == ModeState::leaving; }
  ModeState state() const { return state_; }
  const CrossingView& view() const { return view_; }

  // The seed's rules on echoes in the current frame: an echo too close for the body (min_read
  // along its own bearing) on the left, right or straight ahead (both); the lateral bands for
  // "inside"; the end test on the fresh readings. Pure, for tests.
  static CrossingView look(const ptu::Echoes& e, const PanTiltScan& scan, std::uint64_t tick, const CrossingSettings& s);

 private:
  CrossingOutput out(Steer steer) const;

  CrossingSettings s_;
  SideDistances sides_;
  ModeState state_ = ModeState::off;
  ModeReason reason_ = ModeReason::none;
  std::uint64_t start_tick_ = 0;
  std::uint64_t tick_ = 0;                   // of the current step
  std::uint64_t wait_since_ = 0;             // blocked on both sides since
  bool entered_ = false;                     // has been inside the door
  SectorPose leave_from_{};                  // where the last stretch began
  CrossingView view_{};
};

}  // namespace robuter::doors

// SPDX-License-Identifier: GPL-3.0-or-later
// The passage finder's decisions, pure: stop and scan, find the passage, manoeuvre onto its centre
// line facing it, check again — until aligned, or a reason to give up.
#pragma once

#include <cstdint>

#include "modules/emergency/mode_output.hpp"
#include "modules/executor/go_to.hpp"
#include "modules/gate/door_estimate.hpp"
#include "modules/ptu/scan_view.hpp"
#include "modules/topics.hpp"

namespace robuter::gate {

// Everything the passage finder needs, in its own units (mm, ticks, degrees, cm/s).
struct GateSettings {
  DoorSettings door;                   // how the passage is read from a scan
  std::int32_t min_mm = 700;           // a corner this close: close enough, stop (MIN)
  std::int32_t speed_cm_s = 5;         // driving speed (Va)
  std::int32_t turn_cm_s = 2;          // turning wheel speed (Va/2)
  std::uint32_t timeout_ticks = 1000;  // no lock for this long: no passage (TIMEOUT)
  double stage_mm = 300.0;             // aligned with the front face this far from the passage
  double lateral_tolerance_mm = 30.0;  // aligned: axle this close to the centre line
  double heading_tolerance_deg = 2.0;  // aligned: heading this close to the passage's direction
  double distance_tolerance_mm = 150.0;  // aligned: front face this close to stage_mm (farther: drive on)
  std::uint32_t max_manoeuvres = 6;    // manoeuvres before giving up
  std::uint32_t stall_ticks = 500;     // a manoeuvre that has not moved the robot for this long backs off, ticks
  double back_off_mm = 250.0;          // how far it backs off straight before scanning again, mm
  double agree_mm = 100.0;             // two scans agree when their passage centres are this close, mm
  double agree_deg = 5.0;              // and their directions through it, degrees
  std::uint32_t max_looks = 8;         // scans in a row that disagree with the one before: no passage
  double axle_to_front_mm = 695.0;     // wheel axle to the front face (pan_x + pivot_x), mm
  std::uint32_t settle_ticks = 20;     // still after stopping before a scan counts, ticks
  std::uint32_t scan_timeout_ticks = 1500;  // a complete fresh scan not in after this: scanner trouble, ticks
  std::uint32_t wheel_base_mm = 600;   // DBW, for the manoeuvre controller
};

// One activation's view: the scan, odometry, the pan-tilt's state.
using GateInputs = ptu::ScanInputs;

// One activation's decision: the wish (speeds, state: searching, moving, aligned, failed, off)
// and the passage seen.
struct GateOutput : ModeOutput {
  std::int32_t width_mm = 0;  // estimated passage width, mm
};

class GateLogic {
 public:
  explicit GateLogic(const GateSettings& s);
  // AG: begins from a standstill.
  void start(std::uint64_t tick);
  // Ends now with `reason` (AT: cancelled; an emergency, another motion, the scanner…).
  void fail(ModeReason reason);
  // Ends without a failure (AT while already done or off).
  void stop();
  GateOutput step(const GateInputs& in);
  bool active() const { return phase_ != Phase::idle; }
  const DoorEstimate& last_estimate() const { return estimate_; }
  std::uint32_t manoeuvres() const { return manoeuvres_; }
  // Manoeuvres given up because the robot stood still (held by the safety core) and backed off.
  std::uint32_t back_offs() const { return back_offs_; }
  // Scans whose passage disagreed with the previous scan's (looked at again, not acted on).
  std::uint32_t disagreements() const { return disagreements_; }
  // The last alignment errors measured: lateral (mm, + left of the centre line), heading (degrees).
  double lateral_error_mm() const { return lateral_mm_; }
  double heading_error_deg() const { return heading_deg_; }
  double front_distance_mm() const { return front_mm_; }

 private:
  enum class Phase : std::uint8_t { idle, settle, scan, move, back };
  // Whether the robot has not moved (5 mm, 0.5°) for stall_ticks; notes the pose when it has.
  bool stalled(const GateInputs& in);
  // Begins the phase at `tick`, the pose as the stall watch's reference.
  void enter(Phase p, const GateInputs& in);
  // Reads the fresh scan: lock, estimate, decide aligned / manoeuvre / wait / give up.
  void evaluate(const GateInputs& in);
  GateOutput out(std::int32_t l, std::int32_t r) const;

  GateSettings s_;
  executor::GoToController go_;          // the manoeuvre to the staging pose
  Phase phase_ = Phase::idle;
  ModeState state_ = ModeState::off;   // what is reported
  ModeReason reason_ = ModeReason::none;
  std::uint64_t phase_tick_ = 0;       // when the phase began
  std::uint64_t scan_from_ = 0;        // sectors read after this tick make a fresh scan
  std::uint64_t unlocked_since_ = 0;   // first evaluation without a lock (0: locked or none yet)
  std::uint32_t manoeuvres_ = 0;
  std::uint32_t back_offs_ = 0;        // manoeuvres given up for a back-off in this run, count
  SectorPose moved_pose_{};            // where the robot was when it last moved (stall watch; back-off start)
  SectorPose back_from_{};             // where the back-off began
  // The passage as the previous scan saw it, in the odometry frame (centre and the direction
  // through it): what the next scan must agree with. None at a start.
  bool sighted_ = false;
  executor::PostureUnits sighting_{};
  std::uint32_t disagreements_ = 0;    // scans that disagreed with the one before, this run, count
  std::uint32_t unsettled_ = 0;        // scans in a row without two agreeing, count
  std::uint64_t moved_tick_ = 0;       // when it last moved, ticks
  DoorEstimate estimate_{};
  double lateral_mm_ = 0.0, heading_deg_ = 0.0, front_mm_ = 0.0;
};

}  // namespace robuter::gate

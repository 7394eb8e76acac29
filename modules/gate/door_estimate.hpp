// SPDX-License-Identifier: GPL-3.0-or-later
// Where the passage is, from a stationary pan-tilt scan: its wall line, its two edges, its centre.
#pragma once

#include <cstdint>

#include "modules/gate/corners.hpp"
#include "modules/ptu/echo_points.hpp"

namespace robuter::gate {

// How the estimate reads the scan.
struct DoorSettings {
  ptu::EchoGeometry geometry;      // pan axis, faces, beam, echo grouping
  CornerSettings corners;          // MARGIN, in_door < 8
  std::int32_t max_mm = 2300;      // a corner at or beyond this is no corner (MAX), mm
  double search_deg = 45.0;        // the wall's normal is searched this far either side of the passage, degrees
  double step_deg = 0.25;          // in steps of this, degrees
  int max_wall_sectors = 10;       // wall sectors used on each side of the passage
  double range_sigma_mm = 5.0;     // uncertainty of a range, mm (weighs an edge's range against its bearing)
  double bearing_sigma_deg = 1.5;  // uncertainty of a localised echo's bearing, degrees
};

// The passage in the robot's frame at the scan (x forward, y left, origin the wheel axle), mm.
struct DoorEstimate {
  bool ok = false;                 // a passage was locked and its wall fitted
  double center_x = 0.0;           // middle of the passage, mm
  double center_y = 0.0;           // mm
  double normal_deg = 0.0;         // direction through the passage (the wall's normal, away from the robot), degrees
  double width_mm = 0.0;           // between the two edges, mm
  double right_x = 0.0, right_y = 0.0;  // the right-hand edge, mm
  double left_x = 0.0, left_y = 0.0;    // the left-hand edge, mm
  double wall_rms_mm = 0.0;        // fit residual, mm
  int wall_sectors = 0;            // sectors the wall fit used (edges excluded)
  CornerLock lock;                 // the seed's corners the estimate started from
};

// From a scan taken while the robot stood still (raw ranges along the sector axes, echoes
// localised in `echoes`): the seed's corner lock on the differences; the wall line fitted to the
// sectors beside the passage with the beam model (a sonar reports the in-beam point of a plane
// nearest to it: along the axis within the half-angle of the normal, else at the beam's edge)
// together with the two edge points; then each edge placed on that line at its measured range.
DoorEstimate estimate_door(const PanTiltScan& scan, const ptu::Echoes& echoes, const DoorSettings& s);

}  // namespace robuter::gate

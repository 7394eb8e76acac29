// SPDX-License-Identifier: GPL-3.0-or-later
// Where each pan-tilt echo is: localised within its beam from its neighbours, carried by odometry
// to the robot's current frame. Shared by the passage finder and the door crossing.
#pragma once

#include <array>
#include <cstdint>

#include "modules/ptu/pan_angles.hpp"
#include "modules/topics.hpp"
#include "robot/robot_model.hpp"

namespace robuter::ptu {

// The pan-tilt's geometry (the robot model's mount by default) and how echoes are told apart.
struct EchoGeometry {
  double pivot_x_mm = robot::kRobuter.pan_tilt.pivot_x * 1000.0;      // pan axis ahead of the wheel axle, mm (on the centre line)
  double face_mm = robot::kRobuter.pan_tilt.face_offset * 1000.0;     // pan axis to each transducer face, mm
  double beam_half_deg = robot::kRobuter.pan_tilt.half_angle / robot::kDeg;  // half-angle of a beam, degrees
  std::int32_t same_echo_mm = 20;  // neighbours within this range of each other see the same echo, mm
  std::int32_t far_mm = 2400;      // a reading at or beyond this is "no echo", mm
  std::uint64_t run_window_ticks = 60;  // neighbours read within this of each other belong to one pass, ticks
};

// The echo geometry of a robot model's pan-tilt mount, with the grouping and range limits the
// configuration gives (doors.same_echo_mm, gate.max_mm): one rule for the passage finder and the
// door crossing, which read the same echoes.
EchoGeometry echo_geometry(const robot::RobotModel& m, std::int32_t same_echo_mm, std::int32_t far_mm);

// One sector's echo in the robot's current frame (x forward, y left, origin the wheel axle).
struct Echo {
  bool valid = false;         // read, and younger than the age limit
  bool far = false;           // no echo within range (the point is at the reading, along the axis)
  double bearing_deg = 0.0;   // direction from the pan axis, counter-clockwise from forward, (−180, 180]
  double range_mm = 0.0;      // distance from the pan axis minus the face offset (what a sensor looking that way reads), mm
  double spread_deg = 0.0;    // how far either side of bearing_deg the echo may really be, degrees
  double x_mm = 0.0;          // the point, mm
  double y_mm = 0.0;          // mm
  std::uint64_t tick = 0;     // when it was measured
};
using Echoes = std::array<Echo, kSectors>;

// The bearing interval of sector k's echo, degrees relative to nothing in particular (sector
// angles 5i), from the run of neighbours reading the same range and the neighbours just outside
// the run that read farther (their beams cannot contain the point). Pure, for tests.
struct BearingInterval {
  double low = 0.0;   // degrees
  double high = 0.0;  // degrees
  bool empty() const { return low > high; }
};
BearingInterval echo_interval(const std::array<std::int32_t, kSectors>& range_mm, const std::array<bool, kSectors>& usable,
                              int k, const EchoGeometry& g);

// Every sector's echo: fresh readings only (read within max_age_ticks of now), localised in the
// beam (the axis when the run says nothing), placed with the posture of its firing and carried
// to `now`. Bounded: 72 sectors, runs of at most 2·half-angle/5 + 1 neighbours.
void locate_echoes(const PanTiltScan& scan, const SectorPose& now, std::uint64_t now_tick, std::uint64_t max_age_ticks,
                   const EchoGeometry& g, Echoes& out);

// Angle in degrees brought into (−180, 180].
double wrap_deg(double a);

}  // namespace robuter::ptu

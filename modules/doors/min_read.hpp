// SPDX-License-Identifier: GPL-3.0-or-later
// Door crossing's minimum admissible pan-tilt reading per direction, from the robot's geometry (seed doors.c).
#pragma once

#include <array>
#include <cstdint>

#include "modules/ptu/pan_angles.hpp"
#include "robot/robot_model.hpp"

namespace robuter::doors {

// Where the pan-tilt sits on the body and how much clearance is wanted, in the seed's terms
// (doors.h), mm; made from the robot model by body_geometry().
struct BodyGeometry {
  std::int32_t length_mm = 0;        // body length (ROBOT_LENGTH)
  std::int32_t width_mm = 0;         // body width (ROBOT_WIDTH)
  std::int32_t pan_x_mm = 0;         // pan axis to the front face (PAN_X_POSITION)
  std::int32_t pan_y_mm = 0;         // pan axis to the left side (PAN_Y_POSITION)
  std::int32_t box_width_mm = 0;     // between the two transducer faces (BOX_WIDTH)
  std::int32_t safety_mm = 35;       // clearance kept from obstacles (SAFETY_DIST)
};

// The seed's doors.h numbers of a robot model (the pan axis on the centre line): the Robuter's
// give ROBOT_LENGTH 1025, ROBOT_WIDTH 700, PAN_X_POSITION 725, PAN_Y_POSITION 350, BOX_WIDTH 100.
constexpr BodyGeometry body_geometry(const robot::RobotModel& m, std::int32_t safety_mm = 35) {
  return {robot::mm(m.body.length), robot::mm(m.body.width), robot::mm(m.body.axle_to_front - m.pan_tilt.pivot_x),
          robot::mm(0.5 * m.body.width), robot::mm(2.0 * m.pan_tilt.face_offset), safety_mm};
}

// The four distances, measured from a transducer face, at which the front, rear, left and right
// sides (plus safety) are met along the body's axes: x1…x4 of init_doors(), mm.
struct SideDistances {
  std::int32_t front = 0;  // x1 = PAN_X − BOX/2 + SAFETY
  std::int32_t rear = 0;   // x2 = LENGTH − PAN_X − BOX/2 + SAFETY
  std::int32_t left = 0;   // x3 = PAN_Y − BOX/2 + SAFETY
  std::int32_t right = 0;  // x4 = WIDTH − PAN_Y − BOX/2 + SAFETY
};
SideDistances side_distances(const BodyGeometry& g);

using MinReadTable = std::array<std::int32_t, ptu::kSectors>;  // mm per sector

// init_doors(): sector i looks 5i° counter-clockwise from the front; x1/cos for 0..25° and
// 335..355°, x3/sin on the left (30..135°), x2/cos at the rear (140..225°), x4/sin on the right
// (230..330°), each truncated to whole mm as the seed's long. π is exact here (the seed wrote 3.14).
MinReadTable min_read_table(const BodyGeometry& g);

// The same boundary for any direction (radians, counter-clockwise from the front): the distance
// from a transducer face to the safety rectangle along that ray, the smaller of the side and
// front/rear candidates — equal to the table at every sector the crossing looks at (5..85°,
// 270..350°). Used for echoes placed between sectors.
double min_read_at(const SideDistances& s, double angle_rad);

// The largest boundary over the directions [lo, hi] (radians, hi − lo < π): an echo known only
// to lie somewhere in a beam is judged where the body reaches farthest in it.
double min_read_max(const SideDistances& s, double lo_rad, double hi_rad);

}  // namespace robuter::doors

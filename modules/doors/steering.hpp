// SPDX-License-Identifier: GPL-3.0-or-later
// Door crossing's steering rules on the 72 pan-tilt sectors (seed doors.c, doors()).
#pragma once

#include <cstdint>

#include "modules/doors/min_read.hpp"
#include "modules/ptu/scan_filter.hpp"

namespace robuter::doors {

using ptu::SectorValues;

// Which sectors form each side (seed: left 1..17 = 5..85°, right 54..70 = 270..350°).
struct SideSectors {
  int left_first = 1;    // first left sector checked
  int left_last = 17;    // last left sector checked
  int right_first = 54;  // first right sector checked
  int right_last = 70;   // last right sector checked
};

// Which sides have a reading under the minimum admissible range.
struct SideThreats {
  bool left = false;   // something too close on the left: turn right
  bool right = false;  // something too close on the right: turn left
};

// seed doors(): a reading under min_read on a left sector flags the left, on a right sector the
// right. A reading < 0 means "no reading" and is skipped (the seed compared the zeros of a scan
// not yet taken, which read as obstacles everywhere).
SideThreats side_threats(const SectorValues& readings, const MinReadTable& min_read, const SideSectors& s = {});

// What the robot does about the threats.
enum class Steer : std::uint8_t {
  straight,    // nothing too close: forward, slowly
  turn_left,   // too close on the right only: left wheel back, right wheel still
  turn_right,  // too close on the left only: right wheel back, left wheel still
  stop,        // too close on both sides: stop and wait for fresh readings
};
Steer steer(const SideThreats& t);

// Wheel speeds of a steering decision, cm/s.
struct SteerSpeeds {
  std::int32_t forward_cm_s = 2;  // both wheels going straight (seed: 2)
  std::int32_t back_cm_s = 1;     // the wheel that backs off in a turn (seed: 1)
};
struct Wheels {
  std::int32_t left = 0;   // cm/s
  std::int32_t right = 0;  // cm/s
};
// straight (f, f), turn_left (−b, 0), turn_right (0, −b), stop (0, 0): a turn pivots about
// the still wheel while backing off, so the front moves away from what it nearly touched.
Wheels wheels_for(Steer s, const SteerSpeeds& v = {});

// seed doors()' end test: every left sector 1..18 or every right sector 54..71 at or beyond
// max_dist_mm. A reading < 0 (none) is never beyond.
bool all_clear_on_a_side(const SectorValues& readings, std::int32_t max_dist_mm);

}  // namespace robuter::doors

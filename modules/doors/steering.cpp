// SPDX-License-Identifier: GPL-3.0-or-later
// The seed's reactive rules, one function each.
#include "modules/doors/steering.hpp"

namespace robuter::doors {

SideThreats side_threats(const SectorValues& r, const MinReadTable& min_read, const SideSectors& s) {
  SideThreats t;
  auto under = [&](int i) {
    const std::int32_t v = r[static_cast<std::size_t>(i)];
    return v >= 0 && v < min_read[static_cast<std::size_t>(i)];
  };
  for (int i = s.left_first; i <= s.left_last; ++i) t.left = t.left || under(i);
  for (int i = s.right_first; i <= s.right_last; ++i) t.right = t.right || under(i);
  return t;
}

Steer steer(const SideThreats& t) {
  if (t.left && t.right) return Steer::stop;
  if (t.right) return Steer::turn_left;
  if (t.left) return Steer::turn_right;
  return Steer::straight;
}

Wheels wheels_for(Steer s, const SteerSpeeds& v) {
  switch (s) {
    case Steer::straight: return {v.forward_cm_s, v.forward_cm_s};
    case Steer::turn_left: return {-v.back_cm_s, 0};
    case Steer::turn_right: return {0, -v.back_cm_s};
    case Steer::stop: return {0, 0};
  }
  return {0, 0};
}

// Why the seed's sector ranges differ from side_threats(): its end test also looks straight
// left (18) and at 355° (71).
bool all_clear_on_a_side(const SectorValues& r, std::int32_t max_dist_mm) {
  auto clear = [&](int first, int last) {
    for (int i = first; i <= last; ++i)
      if (r[static_cast<std::size_t>(i)] < max_dist_mm) return false;
    return true;
  };
  return clear(1, 18) || clear(54, 71);
}

}  // namespace robuter::doors

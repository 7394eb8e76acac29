// SPDX-License-Identifier: GPL-3.0-or-later
// Main sensor, watch-dog sets and auto-toggle table: a faithful reading of the seed's emerg.c.
#include "modules/emergency/watchdog_sets.hpp"

#include <cstdlib>

namespace robuter::emergency {

// Going round the ring backwards, as the seed's sub24.
int sub24(int a, int b) {
  const int r = a - b;
  return r < 1 ? r + kRingSize : r;
}

// Going round the ring forwards, as the seed's add24.
int add24(int a, int b) {
  const int r = a + b;
  return r > kRingSize ? r - kRingSize : r;
}

// The seed's get_main_sensor(), branch for branch. The seed tells forward from backward by
// "both wheels positive"; wherever |r| exceeds a threshold both wheels have the same sign (with
// the seed's DBW), so the sign of l + r is the same test and stays right for other wheel bases.
int main_sensor(std::int32_t left, std::int32_t right, std::uint32_t wheel_base_mm) {
  if (left == right) {
    if (left == 0) return 0;
    return left < 0 ? 13 : 1;
  }
  // Same operations in the same order as the seed, so the boundaries round identically.
  double r = (static_cast<double>(left) + static_cast<double>(right)) * 1.0 /
             (static_cast<double>(left) - static_cast<double>(right));
  r = r * static_cast<double>(wheel_base_mm) / 2;
  const bool forward = static_cast<std::int64_t>(left) + right > 0;
  const double a = r < 0 ? -r : r;
  if (a > kLimit12) return forward ? 1 : 13;                                   // straight
  if (a > kLimit23) return forward ? (r > 0 ? 2 : 24) : (r > 0 ? 12 : 14);     // very soft curve
  if (a > kLimit34) return forward ? (r > 0 ? 3 : 23) : (r > 0 ? 11 : 15);     // soft curve
  if (a > kLimit45) return forward ? (r > 0 ? 4 : 22) : (r > 0 ? 10 : 16);     // medium curve
  if (a > kLimit56) return forward ? (r > 0 ? 5 : 21) : (r > 0 ? 9 : 17);      // hard curve
  if (r == 0) return left > 0 ? 7 : 19;                                        // rotation
  const bool left_faster = std::abs(left) > std::abs(right);                  // very hard curve
  if (left > right) return left_faster ? 6 : 18;
  return left_faster ? 8 : 20;
}

// The seed's wds[] table.
WatchSensors watch_sensors(int main) {
  switch (main) {
    case 0: return {0, 0, 0, 0, 0};
    case 7: return {7, 5, 6, 17, 18};
    case 19: return {19, 20, 21, 8, 9};
    case 6: return {6, 5, 7, 18, 24};
    case 8: return {8, 7, 9, 14, 20};
    case 20: return {20, 21, 19, 2, 8};
    case 18: return {18, 17, 19, 12, 6};
    default: return {main, sub24(main, 1), add24(main, 1), sub24(main, 2), add24(main, 2)};
  }
}

// Folds the five sensors into a table.
std::uint32_t watch_mask(int main) {
  std::uint32_t m = 0;
  for (int s : watch_sensors(main))
    if (s >= 1 && s <= kRingSize) m |= sensor_bit(s);
  return m;
}

// The seed's set_table / table_or choice, made a pure function of its inputs.
std::uint32_t select_sensors(std::uint32_t user_table, bool auto_toggle, std::uint32_t watch, bool us_enabled) {
  if (!us_enabled) return user_table & kAllSensors;
  if (auto_toggle) return watch & kAllSensors;
  return (user_table | watch) & kAllSensors;
}

}  // namespace robuter::emergency

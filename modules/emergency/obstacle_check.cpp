// SPDX-License-Identifier: GPL-3.0-or-later
// Safety distance and the watch-dog verdict.
#include "modules/emergency/obstacle_check.hpp"

#include <algorithm>
#include <cstdlib>

namespace robuter::emergency {

// Stopping distance grows with speed, so a slow robot may come closer (seed get_us_limit).
std::uint32_t safety_distance_mm(std::int32_t left, std::int32_t right, std::uint32_t min_mm,
                                 std::uint32_t mm_per_cm_s) {
  const auto fastest = static_cast<std::uint64_t>(std::max(std::abs(static_cast<std::int64_t>(left)),
                                                            std::abs(static_cast<std::int64_t>(right))));
  const std::uint64_t d = std::max<std::uint64_t>(fastest * mm_per_cm_s, min_mm);
  return static_cast<std::uint32_t>(std::min<std::uint64_t>(d, 0xFFFFFFFFu));
}

// An obstacle seen by any sensor trips even while another still lacks data (the seed held
// first and only then looked): the stop is never delayed by a missing neighbour.
WatchVerdict check_watch(const WatchSensors& watch, const UltrasonicRanges& ranges, std::uint32_t safety_mm,
                         std::uint64_t tick, std::uint32_t stale_ticks) {
  WatchVerdict missing;
  for (int s : watch) {
    if (s < 1 || s > kRingSize) continue;
    const auto i = static_cast<std::size_t>(s - 1);
    const std::uint16_t mm = ranges.mm[i];
    const bool stale = tick > ranges.read_tick[i] && tick - ranges.read_tick[i] > stale_ticks;
    if (mm == 0 || stale) {
      if (missing.sensor == 0) missing = {WatchResult::hold, s};
      continue;
    }
    if (mm <= safety_mm) return {WatchResult::obstacle, s};
  }
  return missing;
}

}  // namespace robuter::emergency

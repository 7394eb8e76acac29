// SPDX-License-Identifier: GPL-3.0-or-later
// Safety distance and the verdict of the watch-dog sensors' readings (seed get_us_limit + emergency()).
#pragma once

#include <cstdint>

#include "modules/emergency/watchdog_sets.hpp"
#include "modules/topics.hpp"

namespace robuter::emergency {

// The safety distance for wheel speeds (left, right) in cm/s, mm: the faster wheel's speed
// times `mm_per_cm_s`, never less than `min_mm` (seed: 10 mm per cm/s, at least 220 mm).
std::uint32_t safety_distance_mm(std::int32_t left, std::int32_t right, std::uint32_t min_mm,
                                 std::uint32_t mm_per_cm_s);

// What the watch-dog sensors say about a motion.
enum class WatchResult : std::uint8_t {
  clear,     // every sensor has a fresh reading beyond the safety distance
  hold,      // some sensor has no (fresh) reading yet: wait for data
  obstacle,  // some sensor reads within the safety distance: emergency
};

struct WatchVerdict {
  WatchResult result = WatchResult::clear;  // the verdict
  int sensor = 0;                           // the sensor that decided it (0 when clear)
};

// Checks the five sensors: a reading of 0 or older than `stale_ticks` at `tick` is missing; a
// reading ≤ `safety_mm` is an obstacle (the seed trips at ≤). An obstacle wins over missing data.
WatchVerdict check_watch(const WatchSensors& watch, const UltrasonicRanges& ranges, std::uint32_t safety_mm,
                         std::uint64_t tick, std::uint32_t stale_ticks);

}  // namespace robuter::emergency

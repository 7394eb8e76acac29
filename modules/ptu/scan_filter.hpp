// SPDX-License-Identifier: GPL-3.0-or-later
// The seed's post-processing of a 72-sector scan: range correction, spike filter, differences.
#pragma once

#include <array>
#include <cstdint>

#include "modules/ptu/pan_angles.hpp"

namespace robuter::ptu {

using SectorValues = std::array<std::int32_t, kSectors>;  // one value per 5° sector, mm

// The calibration of the pan-tilt sonars (seed ptu.c, read_pt).
struct RangeCalibration {
  std::int32_t cap_mm = 2491;           // readings above this (and no echo) count as this, mm (PAN_TIME_OUT_DIST)
  std::int32_t offset_mm = 46;          // measured = scale · real + offset: the offset, mm
  std::int32_t scale_permille = 960;    // the scale, ‰ (0.96)
};

// Real range from a measured one: (measured − 46) / 0.96 after capping at the time-out range;
// 0 (no echo) counts as the cap. Truncated towards zero as the seed's long assignment; never
// negative.
std::int32_t correct_range(std::int32_t measured_mm, const RangeCalibration& c = {});

// The spike filter's thresholds (seed gate.h MAX and filter()'s MAX − 1000).
struct SpikeFilter {
  std::int32_t high_mm = 2300;   // a neighbour above this is "high" (seed MAX)
  std::int32_t drop_mm = 1000;   // a value below high_mm − drop_mm between two high ones is a spike
};

// seed filter(): a value below high − drop between two neighbours above high becomes their mean
// (integer division); every other value is copied. The circle wraps (71 and 0 are neighbours).
void spike_filter(const SectorValues& raw, SectorValues& out, const SpikeFilter& f = {});

// seed diff(): out[i] = f[i+1] − f[i], out[71] = f[0] − f[71].
void differences(const SectorValues& filtered, SectorValues& out);

}  // namespace robuter::ptu

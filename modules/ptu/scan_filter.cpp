// SPDX-License-Identifier: GPL-3.0-or-later
// Range correction, spike filter and differences exactly as seed 002's ptu.c.
#include "modules/ptu/scan_filter.hpp"

namespace robuter::ptu {

// Why double: the seed divides by 0.96 in floating point and truncates on assignment to long.
std::int32_t correct_range(std::int32_t measured_mm, const RangeCalibration& c) {
  std::int32_t m = measured_mm;
  if (m <= 0 || m > c.cap_mm) m = c.cap_mm;
  const double real = static_cast<double>(m - c.offset_mm) * 1000.0 / static_cast<double>(c.scale_permille);
  return real <= 0.0 ? 0 : static_cast<std::int32_t>(real);
}

// The seed's three cases (i+1 for i = 0..69, then 71 and 0 across the wrap) are one rule on a
// circle: each value is judged against its two circular neighbours.
void spike_filter(const SectorValues& raw, SectorValues& out, const SpikeFilter& f) {
  for (int i = 0; i < kSectors; ++i) {
    const std::int32_t before = raw[static_cast<std::size_t>(wrap_sector(i - 1))];
    const std::int32_t after = raw[static_cast<std::size_t>(wrap_sector(i + 1))];
    const std::int32_t v = raw[static_cast<std::size_t>(i)];
    const bool spike = before > f.high_mm && v < f.high_mm - f.drop_mm && after > f.high_mm;
    out[static_cast<std::size_t>(i)] = spike ? (before + after) / 2 : v;
  }
}

void differences(const SectorValues& filtered, SectorValues& out) {
  for (int i = 0; i < kSectors; ++i)
    out[static_cast<std::size_t>(i)] =
        filtered[static_cast<std::size_t>(wrap_sector(i + 1))] - filtered[static_cast<std::size_t>(i)];
}

}  // namespace robuter::ptu

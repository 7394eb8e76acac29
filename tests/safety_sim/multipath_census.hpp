// SPDX-License-Identifier: GPL-3.0-or-later
// What echoes clear in the evidence grid, against the simulated world's truth (docs/SAFETY.md §13, "Multipath").
#pragma once

#include <cstdint>
#include <string>

#include "hal/sim/sonar_presets.hpp"
#include "modules/emergency/evidence_grid.hpp"

namespace robuter::test {

// Counts of one census.
struct MultipathCensus {
  long readings = 0;           // ring readings placed in the grid
  long longer_than_truth = 0;  // echoes longer than the ideal model's reading at the same pose (multipath)
  long surface_cleared = 0;    // evidence cells on a real surface (centre within half a cell) that a
                               // multipath echo cleared
  long fresh_cleared = 0;      // of those, cells whose evidence was at most `fresh` ticks old
  long corner_cleared = 0;     // of those, cells within 50 mm of a surface's end (a solid's corner)
  long phantom_cleared = 0;    // evidence cells off every surface that a multipath echo cleared
  long phantom_near = 0;       // evidence cells off every surface within 1.5 m of the robot, summed
                               // over one look a second (cell-seconds: what holds a robot up)
  double travelled = 0.0;      // m the wanderer drove
};

// A wanderer (forward on a slight curve, turning away from what the front sensors hear) in
// `world_file` for `seconds`, its ring fired node by node every 40 ms with the `preset` model
// (seeded), every reading placed at the true pose in an EvidenceGrid of `settings` (no known
// structure: every arc marked whole), the body certified free each tick as the firmware does.
// Before the cone of each echo longer than the ideal model's at the same pose (multipath: the
// ideal model has no indirect path) is certified, the evidence cells it may clear are noted;
// those it did clear are counted, on a surface of the world or off every surface, fresh (marked
// within `fresh` ticks) or not.
MultipathCensus multipath_census(const std::string& world_file, sim::SonarPreset preset, double seconds,
                                 std::uint64_t seed, const emergency::GridSettings& settings, std::uint64_t fresh);

}  // namespace robuter::test

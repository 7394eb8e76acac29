// SPDX-License-Identifier: GPL-3.0-or-later
// The ring's full-scan time (USS) and node time (USN) of a stopped robot, as the link reports them.
#pragma once

#include <string>

#include "kernel/config.hpp"

namespace robuter::test::safety_sim {

// What USS and USN answered, ticks (−1 when a reply was not "S <n>").
struct ScanTime {
  int scan_ticks = -1;  // USS: mean full-scan time, ticks
  int node_ticks = -1;  // USN: mean node time, ticks
  std::string error;    // why the firmware did not run (empty when it did)
};

// Runs the firmware configured by `cfg` in `world` (empty: the default lab), stopped, with every
// sensor on and the seed's settings sent over the link (UT all ones, UD3, Ut33), for `ticks`
// ticks, then asks USS and USN.
ScanTime measure_scan_time(const Config& cfg, const std::string& world = "", int ticks = 1000);

}  // namespace robuter::test::safety_sim

// SPDX-License-Identifier: GPL-3.0-or-later
// What a mode that drives on the pan-tilt's scan reads each activation: the scan, the unit's state, odometry.
#pragma once

#include <cstdint>

#include "modules/topics.hpp"

namespace robuter::ptu {

// One activation's view of a mode driven by the scan (the passage finder, the door crossing).
struct ScanInputs {
  std::uint64_t tick = 0;             // now
  const PanTiltScan* scan = nullptr;  // the latest scan (never null in use)
  SectorPose pose{};                  // odometry now
  bool scanner_failed = false;        // the pan-tilt reports a failure
};

// The topics such a mode reads, and its inputs from them.
class ScanView {
 public:
  explicit ScanView(const Blackboard& bb)
      : scan_(bb.pan_tilt_scan.reader()), ptu_(bb.pan_tilt_status.reader()), posture_(bb.posture.reader()) {}
  // This activation's inputs at `tick`.
  ScanInputs now(std::uint64_t tick) const {
    const Posture& p = posture_.peek();
    return ScanInputs{tick, &scan_.peek(), SectorPose{p.x, p.y, p.theta}, ptu_.peek().state == ModeState::failed};
  }
  // The inputs of the last step at shut-down: the scan alone.
  ScanInputs closing(std::uint64_t tick) const { return ScanInputs{tick, &scan_.peek(), {}, false}; }

 private:
  Reader<PanTiltScan> scan_;  // the 72-sector scan
  Reader<ModeStatus> ptu_;    // the unit's state (failed ends the run)
  Reader<Posture> posture_;   // odometry
};

}  // namespace robuter::ptu

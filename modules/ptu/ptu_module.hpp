// SPDX-License-Identifier: GPL-3.0-or-later
// Pan-tilt module: runs the driver while scanning is wanted and publishes the 72-sector scan.
#pragma once

#include "hal/api/byte_stream.hpp"
#include "hal/api/sonar_ring.hpp"
#include "kernel/process.hpp"
#include "modules/ptu/ptu_driver.hpp"
#include "modules/topics.hpp"

namespace robuter {

// Scanning is wanted while Ap is on, or while the passage finder or the door crossing needs it
// (seed: both read ptu_on's data). A unit that fails is reported in `pan_tilt_status` (XD) and
// the log, and scanning stops until the next start.
class PtuModule final : public Process {
 public:
  // `stream` is the unit's port (null: no unit configured); the module does not own it.
  PtuModule(Blackboard& bb, hal::ByteStream* stream, hal::SonarRing& ring, const ptu::PtuSettings& s);

  bool init(Kernel& k) override;
  void run(Kernel& k) override;
  void close(Kernel& k) override;

  const ptu::PtuDriver& driver() const { return driver_; }

 private:
  // Whether anything wants the scanner now.
  bool wanted() const;
  // Publishes the status when state or reason changed; logs the transition.
  void report(std::uint64_t tick);

  ptu::PtuDriver driver_;
  Reader<ModeRequest> modes_;    // Ap/Ag: its generation tells a new one
  Reader<ModeStatus> gate_;
  Reader<ModeStatus> doors_;
  Reader<Posture> posture_;
  Writer<PanTiltScan> scan_out_;
  Writer<ModeStatus> status_out_;
  bool was_wanted_ = false;  // wanted() at the previous activation
};

}  // namespace robuter

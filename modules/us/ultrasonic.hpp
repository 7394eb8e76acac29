// SPDX-License-Identifier: GPL-3.0-or-later
// Ultrasonic module (seed us.c): fires the ring without blocking and publishes ranges and timing.
#pragma once

#include <cstdint>

#include "hal/api/sonar_ring.hpp"
#include "kernel/clock.hpp"
#include "kernel/config.hpp"
#include "kernel/process.hpp"
#include "modules/topics.hpp"
#include "modules/us/ring_scanner.hpp"

namespace robuter {

class UltrasonicModule final : public Process {
 public:
  // Owns `ring` for the life of the module; `cfg` gives the defaults until the serial module
  // publishes the operator's settings.
  UltrasonicModule(Blackboard& bb, hal::SonarRing& ring, const SonarConfig& cfg);
  // The emergency module, triggered on every new reading so it judges it in the same tick.
  void set_emergency(Process* p) { emergency_ = p; }
  const us::RingScanner& scanner() const { return scanner_; }

  bool init(Kernel& k) override;
  void run(Kernel& k) override;

 private:
  // What to fire: the emergency's selection, the operator's delay and time-out.
  us::ScanRequest request(Nanos tick_ns) const;

  hal::SonarRing& ring_;
  SonarConfig cfg_;
  Reader<UltrasonicSettings> settings_;   // UT/UD/Ut/Uu (serial)
  Reader<SonarSelection> selection_;      // the table that fires (emergency)
  Writer<UltrasonicRanges> ranges_out_;
  Writer<UltrasonicTiming> timing_out_;
  us::RingScanner scanner_;
  Process* emergency_ = nullptr;          // triggered on new ranges
  std::uint64_t lost_logged_ = 0;         // lost reads already logged
  bool watch_ = true;                     // [sonar] schedule = "watch" (else "seed")
};

}  // namespace robuter

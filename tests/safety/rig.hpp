// SPDX-License-Identifier: GPL-3.0-or-later
// The safety core as the firmware runs it: us, emergency and executor in a kernel on a virtual
// clock with the seed's process table, fake HALs and a test double of the link.
#pragma once

#include <array>
#include <cstdint>

#include "kernel/config.hpp"
#include "kernel/kernel.hpp"
#include "modules/emergency/emergency.hpp"
#include "modules/executor/executor.hpp"
#include "modules/topics.hpp"
#include "modules/us/ultrasonic.hpp"
#include "tests/safety/fakes.hpp"
#include "tests/safety/link_double.hpp"

namespace robuter::test {

inline constexpr Nanos kTick = 10 * kNanosPerMilli;  // the seed's 10 ms tick

// Seed 002's kernel.c table for the three modules: name, period, offset, priority, budget. The
// seed's read_sensors offset 6 is not below its period 4, which Kernel::validate refuses: offset
// 2 is the same phase (6 mod 4), only the very first activation comes 4 ticks earlier.
inline std::array<ProcessRow, 3> seed_rows(Process* us, Process* emergency, Process* executor) {
  return {{{"us", us, 4, 2, 2, 2000}, {"emergency", emergency, 10, 4, 5, 2000}, {"executor", executor, 10, 2, 4, 2000}}};
}

// The seed's obstacle rule: the fake ring's scripted per-sensor distances have no geometry, so
// the tests of the gate's emergency logic run on the watch-dog sets; the envelope is tested on
// the simulated robot (tests/safety_sim) and by its own unit tests.
inline Config seed_config() {
  Config c;
  c.emergency.rule = "seed";
  return c;
}

struct Rig {
  explicit Rig(const Config& c = Config{})
      : cfg(c),
        kernel(clock, kTick),
        drive(&bb, &tick_now),
        ring(clock),
        us(bb, ring, cfg.sonar),
        emergency(bb, bumpers, cfg.emergency, cfg.robot),
        executor(bb, drive, cfg.robot),
        link(bb, kernel) {
    us.set_emergency(&emergency);
    emergency.set_executor(&executor);
    link.settings(UltrasonicSettings{0xFFFFFF, cfg.sonar.node_delay_ticks, cfg.sonar.timeout_ms, cfg.emergency.auto_toggle});
    rows = seed_rows(&us, &emergency, &executor);
    ok = !kernel.set_table(rows) && kernel.start();
  }
  ~Rig() { kernel.shutdown(); }

  // Runs n ticks; the fake drive moves the robot by one tick before each.
  void step(int n = 1) {
    for (int i = 0; i < n; ++i) {
      drive.advance(static_cast<double>(kTick) / 1e9);
      tick_now = kernel.tick();
      kernel.step();
    }
  }
  // Runs until `pred()` or `limit` ticks; true when it became true.
  template <typename P>
  bool step_until(P pred, int limit) {
    for (int i = 0; i < limit; ++i) {
      if (pred()) return true;
      step();
    }
    return pred();
  }
  const EmergencyState& state() const { return bb.emergency.reader().peek(); }
  const MotionCommand& command() const { return bb.motion_command.reader().peek(); }
  const UltrasonicRanges& ranges() const { return bb.ranges.reader().peek(); }
  const Posture& posture() const { return bb.posture.reader().peek(); }

  Config cfg;
  VirtualClock clock;
  Kernel kernel;
  Blackboard bb;
  std::uint64_t tick_now = 0;  // the tick being run, stamped on drive commands
  FakeDrive drive;
  FakeRing ring;
  FakeBumpers bumpers;
  UltrasonicModule us;
  EmergencyModule emergency;
  ExecutorModule executor;
  LinkDouble link;
  std::array<ProcessRow, 3> rows{};
  bool ok = false;
};

}  // namespace robuter::test

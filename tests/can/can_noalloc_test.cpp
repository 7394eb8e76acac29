// SPDX-License-Identifier: GPL-3.0-or-later
// Proves the CAN protocol path allocates nothing once started: 10,000 ticks of the backend with
// two simulated drives and six sonar nodes through enable, motion, faults, recovery, heartbeat
// loss, bus states and ring firings, every malloc of the thread counted.
#include <gtest/gtest.h>

#include "kernel/log.hpp"
#include "tests/can/can_rig.hpp"
#include "tests/support/alloc_counter.hpp"

namespace robuter::test {
namespace {

TEST(CanNoAlloc, TenThousandTicksOfTheCanBackendAllocateNothing) {
#if defined(ROBUTER_SANITIZE)
  GTEST_SKIP() << "the sanitizers own malloc; this proof runs in the normal build";
#else
  log::set_level(log::Level::debug);
  CanRig r;
  for (int n = 0; n < 6; ++n)
    for (int i = 0; i < 4; ++i) r.nodes[n]->set_range(i, 2000);
  r.ticks(50);  // bring-up
  ASSERT_EQ(r.drive().health(), hal::DriveHealth::ok);
  r.ring().configure(33, 300);
  std::uint64_t ok_ticks = 0, reads = 0;
  {
    AllocCounter counter;
    for (int i = 0; i < 10'000; ++i) {
      switch (i % 1000) {
        case 0: r.drive().set_servo(true); r.drive().command_wheels(30, 30); break;
        case 100: r.drive().command_wheels(-20, 20); break;
        case 200: r.left.inject_fault(0x2310); break;
        case 210: r.drive().set_servo(false); break;
        case 250: r.left.clear_fault_cause(); break;
        case 400: r.right.set_silent(true); break;
        case 450: r.right.set_silent(false); break;
        case 500: r.bus.set_state(hal::can::BusState::passive); break;
        case 520: r.bus.set_state(hal::can::BusState::off); break;
        case 540: r.bus.set_state(hal::can::BusState::active); break;
        case 600: r.left.reboot(r.now); break;
        default: break;
      }
      const int node = i % 6;
      hal::NodeRanges mm{};
      if (r.ring().read(node, mm)) ++reads;
      r.ring().fire(node, 0x0F);
      r.tick();
      if (r.drive().health() == hal::DriveHealth::ok) ++ok_ticks;
    }
    EXPECT_EQ(counter.count(), 0u);
  }
  EXPECT_GT(ok_ticks, 5000u);  // it recovered from every injected problem
  EXPECT_GT(reads, 1000u);
  log::flush();
#endif
}

}  // namespace
}  // namespace robuter::test

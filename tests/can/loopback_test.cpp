// SPDX-License-Identifier: GPL-3.0-or-later
// The CAN protocol on an in-process loopback bus: simulated drives through bring-up, enable,
// velocity, fault and recovery; heartbeat loss, bus states, odometry and the sonar nodes.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hal/linux/can/sonar_frames.hpp"
#include "tests/can/can_rig.hpp"

namespace robuter::test {
namespace {

using hal::DriveHealth;
using hal::can::BusState;
using hal::can::DriveFault;
using hal::can::LinkPhase;
using State = hal::can::cia402::State;

// Drains `ep` and counts the frames with id `id`.
int count_id(hal::can::LoopbackEndpoint& ep, canid_t id, can_frame* last = nullptr) {
  int n = 0;
  can_frame f;
  while (ep.receive(f))
    if (f.can_id == id) {
      ++n;
      if (last) *last = f;
    }
  return n;
}

TEST(CanLoopback, BringUpConfiguresStartsAndParksInSwitchedOn) {
  CanRig r;
  EXPECT_EQ(r.drive().health(), DriveHealth::silent);  // nothing heard yet
  ASSERT_TRUE(r.until([&] { return r.drive().health() == DriveHealth::ok; }, 50));
  EXPECT_EQ(r.left.mode(), 3);              // 0x6060 = profile velocity
  EXPECT_EQ(r.right.mode(), 3);
  EXPECT_EQ(r.left.heartbeat_ms(), 100);    // 0x1017 written
  EXPECT_EQ(r.left.nmt_state(), hal::can::cia402::NmtState::operational);
  ASSERT_TRUE(r.until([&] { return r.left.state() == State::switched_on && r.right.state() == State::switched_on; }, 20));
  r.ticks(20);
  EXPECT_EQ(r.left.state(), State::switched_on);  // servo off: power stage off, not enabled
  EXPECT_EQ(r.drive().left().status().phase, LinkPhase::running);
  EXPECT_EQ(r.drive().left().status().state, State::switched_on);
  std::int32_t l = 1, rr = 1;
  r.drive().commanded(l, rr);
  EXPECT_EQ(l, 0);
  EXPECT_EQ(rr, 0);
}

TEST(CanLoopback, EnableVelocityAndOdometry) {
  CanRig r;
  ASSERT_TRUE(r.until([&] { return r.drive().health() == DriveHealth::ok; }, 50));
  r.drive().set_servo(true);
  r.drive().command_wheels(50, 50);  // 0.5 m/s straight
  ASSERT_TRUE(r.until([&] { return r.left.state() == State::operation_enabled && r.right.state() == State::operation_enabled; }, 10));
  // 50 cm/s on a 200 mm wheel with 16384 increments per turn: 50 / (π·20) · 16384 = 13038 increments/s.
  const auto expect = static_cast<std::int32_t>(std::lround(50.0 / (std::numbers::pi * 20.0) * 16384.0));
  r.ticks(2);
  EXPECT_EQ(r.left.target_velocity(), expect);
  EXPECT_EQ(r.right.target_velocity(), -expect);  // mounted mirrored: right_invert
  std::int32_t l = 0, rr = 0;
  r.drive().commanded(l, rr);
  EXPECT_EQ(l, 50);
  EXPECT_EQ(rr, 50);
  const hal::Odometry start = r.drive().odometry();
  r.ticks(100);  // 1 s
  const hal::Odometry end = r.drive().odometry();
  EXPECT_NEAR(end.x_m - start.x_m, 0.5, 0.02);
  EXPECT_NEAR(end.y_m - start.y_m, 0.0, 1e-6);
  EXPECT_NEAR(end.theta_rad, 0.0, 1e-6);
  // Turn in place: ±10 cm/s on a 600 mm axle = 1/3 rad/s.
  r.drive().command_wheels(-10, 10);
  const double theta0 = r.drive().odometry().theta_rad;
  r.ticks(150);
  EXPECT_NEAR(r.drive().odometry().theta_rad - theta0, 0.5, 0.02);
  // Servo off: disable operation, wheels stop, the drive parks in "switched on".
  r.drive().set_servo(false);
  r.ticks(3);
  EXPECT_EQ(r.left.state(), State::switched_on);
  EXPECT_EQ(r.left.velocity(), 0.0);
}

// A stop must not wait for the next activation: the RPDO1 with zero goes out in the call.
TEST(CanLoopback, StopGoesOutImmediately) {
  CanRig r;
  ASSERT_TRUE(r.until([&] { return r.drive().health() == DriveHealth::ok; }, 50));
  r.drive().set_servo(true);
  r.drive().command_wheels(30, 30);
  r.ticks(10);
  count_id(r.tap, 0x201);
  r.drive().command_wheels(0, 0);
  can_frame f{};
  ASSERT_EQ(count_id(r.tap, 0x201, &f), 1);
  EXPECT_EQ(f.data[2] | f.data[3] | f.data[4] | f.data[5], 0);  // target velocity 0
  r.drive().set_servo(false);
  ASSERT_EQ(count_id(r.tap, 0x201, &f), 1);
  EXPECT_EQ(f.data[0], 0x07);  // disable operation
}

TEST(CanLoopback, DriveFaultThenRecovery) {
  Config c;
  CanRig r(c);
  ASSERT_TRUE(r.until([&] { return r.drive().health() == DriveHealth::ok; }, 50));
  r.drive().set_servo(true);
  r.drive().command_wheels(40, 40);
  r.ticks(10);
  ASSERT_EQ(r.left.state(), State::operation_enabled);
  r.left.inject_fault(0x2310);  // over-current
  r.tick();
  EXPECT_EQ(r.drive().health(), DriveHealth::fault);  // the EMCY alone is enough
  EXPECT_EQ(r.drive().left().status().emcy_code, 0x2310);
  EXPECT_EQ(r.drive().left_fault(), DriveFault::fault);
  std::int32_t l = 1, rr = 1;
  r.drive().commanded(l, rr);
  EXPECT_EQ(l, 0);
  r.ticks(2);
  EXPECT_EQ(r.drive().right().status().controlword, 0x07);  // the healthy wheel is disabled too
  EXPECT_EQ(r.right.velocity(), 0.0);
  r.drive().set_servo(false);  // what the executor does
  // The cause persists: fault resets (every second) fail.
  r.ticks(250);
  EXPECT_EQ(r.left.state(), State::fault);
  EXPECT_EQ(r.drive().health(), DriveHealth::fault);
  // The cause goes: the next reset pulse takes it out of fault; it climbs back to switched on.
  r.left.clear_fault_cause();
  ASSERT_TRUE(r.until([&] { return r.drive().health() == DriveHealth::ok; }, 150));
  EXPECT_FALSE(r.drive().left().status().emcy_active);
  ASSERT_TRUE(r.until([&] { return r.left.state() == State::switched_on; }, 10));
  r.drive().set_servo(true);
  r.drive().command_wheels(20, 20);
  ASSERT_TRUE(r.until([&] { return r.left.state() == State::operation_enabled && r.left.velocity() > 0.0; }, 10));
}

TEST(CanLoopback, FaultFromStatuswordAlone) {
  CanRig r;
  ASSERT_TRUE(r.until([&] { return r.drive().health() == DriveHealth::ok; }, 50));
  // A drive whose EMCY was lost still reports the fault bit: the TPDO1 is enough.
  r.left.inject_fault(0x3210);
  can_frame f;
  while (r.host.receive(f)) {}  // the EMCY never reaches the host
  r.ticks(2);
  EXPECT_EQ(r.drive().left().status().state, State::fault);
  EXPECT_EQ(r.drive().health(), DriveHealth::fault);
}

TEST(CanLoopback, HeartbeatLossAndReturn) {
  CanRig r;
  ASSERT_TRUE(r.until([&] { return r.drive().health() == DriveHealth::ok; }, 50));
  r.right.set_silent(true);
  r.ticks(30);  // 300 ms < 350 ms time-out
  EXPECT_EQ(r.drive().health(), DriveHealth::ok);
  ASSERT_TRUE(r.until([&] { return r.drive().health() == DriveHealth::silent; }, 10));
  EXPECT_EQ(r.drive().right_fault(), DriveFault::heartbeat_lost);
  EXPECT_EQ(r.drive().left_fault(), DriveFault::none);
  r.right.set_silent(false);
  ASSERT_TRUE(r.until([&] { return r.drive().health() == DriveHealth::ok; }, 20));
}

TEST(CanLoopback, AbsentDriveIsLost) {
  CanRig r;
  r.right.set_silent(true);  // powered off from the start: no answer to any SDO write
  r.ticks(30);
  EXPECT_EQ(r.drive().health(), DriveHealth::fault);  // within the time-out: not operational yet
  ASSERT_TRUE(r.until([&] { return r.drive().health() == DriveHealth::silent; }, 10));
  EXPECT_EQ(r.drive().right().status().phase, LinkPhase::configure_mode);
  r.right.set_silent(false);  // powered on: SDO retries bring it up
  ASSERT_TRUE(r.until([&] { return r.drive().health() == DriveHealth::ok; }, 50));
}

TEST(CanLoopback, BusStates) {
  CanRig r;
  ASSERT_TRUE(r.until([&] { return r.drive().health() == DriveHealth::ok; }, 50));
  r.bus.set_state(BusState::warning);
  r.tick();
  EXPECT_EQ(r.drive().health(), DriveHealth::ok);  // warning: reported only
  r.bus.set_state(BusState::passive);
  r.tick();
  EXPECT_EQ(r.drive().health(), DriveHealth::bus_passive);
  r.bus.set_state(BusState::off);
  r.tick();
  EXPECT_EQ(r.drive().health(), DriveHealth::bus_off);
  const auto sent = r.host.counters().send_failed;
  r.drive().set_servo(true);
  EXPECT_GT(r.host.counters().send_failed, sent);  // nothing leaves a bus-off controller
  r.drive().set_servo(false);
  r.bus.set_state(BusState::active);
  ASSERT_TRUE(r.until([&] { return r.drive().health() == DriveHealth::ok; }, 10));
}

TEST(CanLoopback, RebootedDriveIsBroughtUpAgainWithoutOdometryJump) {
  CanRig r;
  ASSERT_TRUE(r.until([&] { return r.drive().health() == DriveHealth::ok; }, 50));
  r.ticks(5);
  const hal::Odometry before = r.drive().odometry();
  r.left.reboot(r.now);
  r.left.set_position(123456.0);  // its counter starts elsewhere
  r.ticks(2);
  EXPECT_NE(r.drive().health(), DriveHealth::ok);
  ASSERT_TRUE(r.until([&] { return r.drive().health() == DriveHealth::ok; }, 50));
  EXPECT_EQ(r.left.mode(), 3);
  EXPECT_GE(r.drive().left().status().restarts, 1u);
  r.ticks(5);
  EXPECT_NEAR(r.drive().odometry().x_m, before.x_m, 1e-9);
  EXPECT_NEAR(r.drive().odometry().theta_rad, before.theta_rad, 1e-9);
}

TEST(CanLoopback, SdoAbortIsAFault) {
  CanRig r;
  r.left.refuse_mode(true);
  r.ticks(20);
  EXPECT_EQ(r.drive().health(), DriveHealth::fault);
  EXPECT_EQ(r.drive().left().status().sdo_abort, 0x06090030u);
  r.left.refuse_mode(false);  // retried every fault_reset_ms
  ASSERT_TRUE(r.until([&] { return r.drive().health() == DriveHealth::ok; }, 150));
}

TEST(CanLoopback, OdometryCountersWrap) {
  CanRig r;
  r.left.set_position(2147483000.0);   // near INT32_MAX
  r.right.set_position(-2147483000.0);
  ASSERT_TRUE(r.until([&] { return r.drive().health() == DriveHealth::ok; }, 50));
  r.drive().set_servo(true);
  r.drive().command_wheels(50, 50);
  r.ticks(100);
  EXPECT_NEAR(r.drive().odometry().x_m, 0.49, 0.03);  // passes the wrap without a jump
  EXPECT_NEAR(r.drive().odometry().theta_rad, 0.0, 1e-6);
}

TEST(CanLoopback, SonarNodesStartFireAndAnswer) {
  CanRig r;
  for (int n = 0; n < 6; ++n)
    for (int i = 0; i < 4; ++i) r.nodes[n]->set_range(i, static_cast<std::uint16_t>(1000 + 100 * n + i));
  ASSERT_TRUE(r.until([&] { return r.ring().alive(0) && r.ring().alive(5); }, 40));
  EXPECT_FALSE(r.ring().alive(7));  // no pan-tilt node on this bus
  r.ring().configure(33, 300);
  ASSERT_TRUE(r.ring().fire(2, 0x0B));
  EXPECT_FALSE(r.ring().fire(2, 0x0B));  // busy
  hal::NodeRanges mm{};
  EXPECT_FALSE(r.ring().read(2, mm));
  ASSERT_TRUE(r.until([&] { return r.ring().read(2, mm); }, 6));
  EXPECT_EQ(mm[0], 1200);
  EXPECT_EQ(mm[1], 1201);
  EXPECT_EQ(mm[2], 0);  // not fired
  EXPECT_EQ(mm[3], 1203);
  EXPECT_FALSE(r.ring().fire(7, 1));
  // Beyond the time-out's reach (33 ms · 300 m/s / 2 = 4950 mm): no echo.
  r.nodes[1]->set_range(0, 6000);
  ASSERT_TRUE(r.ring().fire(1, 0x01));
  ASSERT_TRUE(r.until([&] { return r.ring().read(1, mm); }, 6));
  EXPECT_EQ(mm[0], 0);
}

TEST(CanLoopback, AFiringCarriesItsOwnTimeOutAndTheNodeAnswersOnceItsEchoesAreIn) {
  CanRig r;
  r.nodes[4]->set_range(0, 600);
  r.nodes[4]->set_range(1, 900);
  r.nodes[4]->set_range(2, 2000);
  ASSERT_TRUE(r.until([&] { return r.ring().alive(4); }, 40));
  r.ring().configure(33, 300);
  can_frame f;
  while (r.tap.receive(f)) {
  }
  // Shortened to 8 ms (1200 mm): 600 and 900 mm are in after 6 ms, 2000 mm is out of reach.
  ASSERT_TRUE(r.ring().fire(4, 0x07, 8));
  ASSERT_TRUE(r.tap.receive(f));
  hal::can::sonar::FireRequest req;
  ASSERT_TRUE(hal::can::sonar::parse_fire(f, req));
  EXPECT_EQ(req.mask, 0x07);
  EXPECT_EQ(req.timeout_ms, 8) << "the fire frame carries the firing's own time-out";
  hal::NodeRanges mm{};
  ASSERT_TRUE(r.until([&] { return r.ring().read(4, mm); }, 2)) << "answered after 8 ms, not 33";
  EXPECT_EQ(mm[0], 600);
  EXPECT_EQ(mm[1], 900);
  EXPECT_EQ(mm[2], 0);
  // The full time-out: 2000 mm is heard after 13.3 ms, the node answers then.
  ASSERT_TRUE(r.ring().fire(4, 0x07));
  ASSERT_TRUE(r.until([&] { return r.ring().read(4, mm); }, 3));
  EXPECT_EQ(mm[2], 2000);
  // A transducer with nothing in reach keeps the node listening to its time-out (33 ms).
  r.nodes[4]->set_range(2, 6000);
  ASSERT_TRUE(r.ring().fire(4, 0x07, 0));
  r.ticks(4);
  EXPECT_FALSE(r.ring().read(4, mm)) << "not before the 33 ms time-out";
  ASSERT_TRUE(r.until([&] { return r.ring().read(4, mm); }, 2));
  EXPECT_EQ(mm[2], 0);
  // A time-out longer than the configured one is not taken: the configured one caps it.
  ASSERT_TRUE(r.ring().fire(4, 0x01, 100));
  ASSERT_TRUE(r.tap.receive(f) && hal::can::sonar::parse_fire(f, req));
  EXPECT_EQ(req.timeout_ms, 33);
}

TEST(CanLoopback, FaultyTransducerAndSilentNodeGiveNoData) {
  CanRig r;
  ASSERT_TRUE(r.until([&] { return r.ring().alive(0) && r.ring().alive(3); }, 40));
  r.nodes[3]->set_faulty(0x02);
  r.ticks(11);  // a status frame carries the mask
  ASSERT_TRUE(r.ring().fire(3, 0x03));
  hal::NodeRanges mm{};
  r.ticks(10);
  EXPECT_FALSE(r.ring().read(3, mm));  // never "no echo" for a broken transducer
  EXPECT_EQ(r.ring().faulty(3), 0x02);
  r.nodes[0]->set_silent(true);
  ASSERT_TRUE(r.until([&] { return !r.ring().alive(0); }, 40));
  EXPECT_FALSE(r.ring().fire(0, 0x0F));
}

}  // namespace
}  // namespace robuter::test

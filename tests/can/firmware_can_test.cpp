// SPDX-License-Identifier: GPL-3.0-or-later
// The whole firmware on the CAN backends over a loopback bus with simulated drives and sonar
// nodes, on the virtual clock: move, then heartbeat loss, drive fault, error-passive and bus-off
// each end in an emergency whose cause XE shows; recovery after a drive fault; without a pan-tilt
// port, Ap/AG/Ad answer no-unit.
#include <gtest/gtest.h>

#include <array>
#include <memory>
#include <sstream>
#include <string>

#include "hal/linux/can/can_backend.hpp"
#include "hal/linux/can/loopback_bus.hpp"
#include "hal/linux/can/sim_nodes.hpp"
#include "modules/firmware/sim_firmware.hpp"

namespace robuter::test {
namespace {

using hal::can::BusState;
using State = hal::can::cia402::State;

// robuterd with [hardware] drive = sonar = "can" on a loopback bus; the simulated nodes step
// after every kernel tick at the kernel's time.
struct CanRobot {
  explicit CanRobot(Config cfg = Config{}) {
    cfg.hardware.drive = "can";
    cfg.hardware.sonar = "can";
    left = std::make_unique<hal::can::SimDriveNode>(bus.attach("left"), 1);
    right = std::make_unique<hal::can::SimDriveNode>(bus.attach("right"), 2);
    for (int n = 0; n < 6; ++n) {
      nodes[n] = std::make_unique<hal::can::SimSonarNode>(bus.attach("sonar"), static_cast<std::uint8_t>(16 + n));
      for (int i = 0; i < 4; ++i) nodes[n]->set_range(i, 3000);  // open space all round
    }
    FirmwareOptions opt;
    opt.can_transport = &bus.attach("robuterd");
    fw = std::make_unique<SimFirmware>(cfg, opt);
    fw->set_tick_observer([this] {
      const std::int64_t now = fw->kernel().now() / 1000;
      left->step(now);
      right->step(now);
      for (auto& n : nodes) n->step(now);
    });
  }
  const EmergencyState& emergency() { return fw->bb().emergency.reader().peek(); }
  const Posture& posture() { return fw->bb().posture.reader().peek(); }
  // The cause word of an XE reply ("E held latched cause enabled clock").
  std::string xe_cause() {
    const auto r = fw->ask("XE");
    if (!r) return "(no reply)";
    std::istringstream in(*r);
    std::string e, held, latched, cause;
    in >> e >> held >> latched >> cause;
    return latched == "1" ? cause : "(not latched: " + *r + ")";
  }
  // Boots, switches the servo on and drives forward at 20 cm/s until both wheels turn.
  void boot_and_move() {
    ASSERT_TRUE(fw->ok()) << fw->error();
    ASSERT_TRUE(fw->run_until(
        [&] { return posture().drive_health == hal::DriveHealth::ok && fw->bb().ranges.reader().peek().scans > 1; }, 300))
        << "drives never became ready";
    ASSERT_EQ(fw->ask("ASN"), "ack");
    ASSERT_EQ(fw->ask("AM 20 20"), "ack");
    ASSERT_TRUE(fw->run_until([&] { return left->velocity() > 0 && right->velocity() < 0; }, 50)) << "wheels never turned";
    fw->run_ticks(50);
    ASSERT_GT(posture().x, 500) << "odometry from the encoders moved the robot (0.1 mm)";
    ASSERT_FALSE(emergency().latched);
  }

  hal::can::LoopbackBus bus;
  std::unique_ptr<hal::can::SimDriveNode> left, right;
  std::array<std::unique_ptr<hal::can::SimSonarNode>, 6> nodes;
  std::unique_ptr<SimFirmware> fw;
};

// The deploy rehearsal's check (tools/vm/guest/guest-checks.py): ASN alone, no motion asked,
// enables both drives over CiA 402 and BO says servo 1.
TEST(CanFirmware, ServoOnAloneEnablesTheDrives) {
  CanRobot r;
  ASSERT_TRUE(r.fw->ok()) << r.fw->error();
  // As in the VM: the operator's ASN as soon as robuterd answers, before the drives are ready
  // (it was acknowledged and lost: the drives stayed disabled until a motion was asked).
  ASSERT_NE(r.posture().drive_health, hal::DriveHealth::ok);
  ASSERT_EQ(r.fw->ask("ASN"), "ack");
  ASSERT_TRUE(r.fw->run_until([&] { return r.posture().servo; }, 300)) << "BO servo never 1";
  EXPECT_TRUE(r.fw->run_until([&] { return r.left->state() == State::operation_enabled; }, 100));
}

// An ASN waiting for the drives ends with an emergency: after the stop byte and XR the servo
// stays off (nothing switches on by itself).
TEST(CanFirmware, AWaitingServoOnEndsWithAnEmergency) {
  CanRobot r;
  ASSERT_TRUE(r.fw->ok()) << r.fw->error();
  ASSERT_EQ(r.fw->ask("ASN"), "ack");
  r.fw->send_raw("\x18");
  ASSERT_TRUE(r.fw->run_until([&] { return r.emergency().latched; }, 50));
  ASSERT_TRUE(r.fw->run_until([&] { return r.posture().drive_health == hal::DriveHealth::ok; }, 300));
  r.fw->run_ticks(20);
  EXPECT_EQ(r.fw->ask("XR"), "ack");
  EXPECT_FALSE(r.fw->run_until([&] { return r.posture().servo; }, 300)) << "the servo switched on by itself";
}

TEST(CanFirmware, BootsEnablesAndDrivesOnTheBus) {
  CanRobot r;
  r.boot_and_move();
  EXPECT_EQ(r.left->state(), State::operation_enabled);
  EXPECT_EQ(r.posture().left, 20);
  const auto bo = r.fw->ask("BO");
  ASSERT_TRUE(bo);
  EXPECT_EQ(r.fw->ask("AM 0 0"), "ack");
  ASSERT_TRUE(r.fw->run_until([&] { return r.left->velocity() == 0.0; }, 20));
  EXPECT_EQ(r.fw->ask("ASF"), "ack");
  ASSERT_TRUE(r.fw->run_until([&] { return r.left->state() == State::switched_on; }, 20));
}

TEST(CanFirmware, HeartbeatLossEndsInEmergency) {
  CanRobot r;
  r.boot_and_move();
  r.left->set_silent(true);
  ASSERT_TRUE(r.fw->run_until([&] { return r.emergency().latched; }, 60));  // 350 ms time-out + one period
  EXPECT_EQ(r.emergency().cause, EmergencyCause::heartbeat_lost);
  EXPECT_EQ(r.xe_cause(), "heartbeat-lost");
  ASSERT_TRUE(r.fw->run_until([&] { return r.right->velocity() == 0.0; }, 20)) << "the other wheel stops too";
  EXPECT_EQ(r.fw->ask("XR"), "error") << "refused while the drive is silent";
  r.left->set_silent(false);
  ASSERT_TRUE(r.fw->run_until([&] { return r.posture().drive_health == hal::DriveHealth::ok; }, 50));
  r.fw->run_ticks(20);
  EXPECT_EQ(r.fw->ask("XR"), "ack");
}

TEST(CanFirmware, DriveFaultEndsInEmergencyAndRecovers) {
  CanRobot r;
  r.boot_and_move();
  r.right->inject_fault(0x2310);  // over-current: EMCY, then fault
  ASSERT_TRUE(r.fw->run_until([&] { return r.emergency().latched; }, 20));
  EXPECT_EQ(r.emergency().cause, EmergencyCause::drive_fault);
  EXPECT_EQ(r.xe_cause(), "drive-fault");
  ASSERT_TRUE(r.fw->run_until([&] { return r.left->velocity() == 0.0; }, 20));
  r.fw->run_ticks(200);
  EXPECT_EQ(r.right->state(), State::fault) << "fault resets fail while the cause is there";
  EXPECT_EQ(r.fw->ask("XR"), "error");
  r.right->clear_fault_cause();
  ASSERT_TRUE(r.fw->run_until([&] { return r.posture().drive_health == hal::DriveHealth::ok; }, 150)) << "fault reset never took";
  r.fw->run_ticks(20);
  EXPECT_EQ(r.fw->ask("XR"), "ack");
  EXPECT_EQ(r.fw->ask("ASN"), "ack");
  EXPECT_EQ(r.fw->ask("AM 15 15"), "ack");
  ASSERT_TRUE(r.fw->run_until([&] { return r.right->state() == State::operation_enabled && r.right->velocity() < 0; }, 30))
      << "moves again after recovery";
}

// A drive without EMCY: the statusword's fault bit (TPDO1) alone trips the emergency.
TEST(CanFirmware, StatuswordFaultAloneEndsInEmergency) {
  CanRobot r;
  r.boot_and_move();
  r.left->set_emcy(false);
  r.left->inject_fault(0x7300);
  ASSERT_TRUE(r.fw->run_until([&] { return r.emergency().latched; }, 20));
  EXPECT_EQ(r.emergency().cause, EmergencyCause::drive_fault);
  EXPECT_EQ(r.xe_cause(), "drive-fault");
  EXPECT_EQ(r.fw->firmware().can()->drive()->left().status().emcy_code, 0) << "no EMCY was sent";
  ASSERT_TRUE(r.fw->run_until([&] { return r.right->velocity() == 0.0; }, 20));
}

TEST(CanFirmware, ErrorPassiveEndsInEmergency) {
  CanRobot r;
  r.boot_and_move();
  r.bus.set_state(BusState::passive);
  ASSERT_TRUE(r.fw->run_until([&] { return r.emergency().latched; }, 20));
  EXPECT_EQ(r.emergency().cause, EmergencyCause::bus_passive);
  EXPECT_EQ(r.xe_cause(), "bus-error-passive");
  ASSERT_TRUE(r.fw->run_until([&] { return r.left->velocity() == 0.0 && r.right->velocity() == 0.0; }, 20));
  r.bus.set_state(BusState::active);
  r.fw->run_ticks(20);
  EXPECT_EQ(r.fw->ask("XR"), "ack");
}

TEST(CanFirmware, BusOffEndsInEmergency) {
  CanRobot r;
  r.boot_and_move();
  r.bus.set_state(BusState::off);
  ASSERT_TRUE(r.fw->run_until([&] { return r.emergency().latched; }, 20));
  EXPECT_EQ(r.emergency().cause, EmergencyCause::bus_off);
  EXPECT_EQ(r.xe_cause(), "bus-off");
  EXPECT_EQ(r.fw->ask("XR"), "error") << "refused while the controller is bus-off";
  r.bus.set_state(BusState::active);
  // The drives lost their host's RPDOs only; back on the bus, they are still there.
  ASSERT_TRUE(r.fw->run_until([&] { return r.posture().drive_health == hal::DriveHealth::ok; }, 50));
}

// With an ultrasonic node gone silent the gate has no data for its watch-dog sensors: the
// motion is held, never granted on stale or missing ranges.
TEST(CanFirmware, SilentSonarNodeHoldsMotion) {
  CanRobot r;
  r.boot_and_move();
  for (auto& n : r.nodes) n->set_silent(true);
  ASSERT_TRUE(r.fw->run_until([&] { return r.posture().left == 0; }, 400));
  EXPECT_EQ(r.left->velocity(), 0.0);
}

// On the robot without [ptu] port there is no pan-tilt unit: Ap, AG and Ad answer error (verbose
// 16 no-unit) instead of ack, before any emergency check; switching off stays ack.
TEST(CanFirmware, WithoutAPanTiltPortApAgAdAnswerNoUnit) {
  CanRobot r;
  ASSERT_TRUE(r.fw->ok()) << r.fw->error();
  r.fw->run_ticks(20);
  for (const char* l : {"Ap", "AG", "Ad"}) EXPECT_EQ(r.fw->ask(l), "error") << l;
  EXPECT_EQ(r.fw->ask("XB1"), "ack");
  for (const char* l : {"Ap", "AG", "Ad"}) EXPECT_EQ(r.fw->ask(l), "error 16 no-unit") << l;
  for (const char* l : {"Ag", "AT", "Af"}) EXPECT_EQ(r.fw->ask(l), "ack") << l;
  EXPECT_FALSE(r.fw->bb().modes.reader().peek().pan_tilt);
}

}  // namespace
}  // namespace robuter::test

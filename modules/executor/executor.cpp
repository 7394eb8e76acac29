// SPDX-License-Identifier: GPL-3.0-or-later
// Executor glue: odometry out, servo and odometry requests, the granted command, the go-to.
#include "modules/executor/executor.hpp"

#include <algorithm>
#include <cstdlib>

#include "kernel/kernel.hpp"
#include "kernel/log.hpp"

namespace robuter {

namespace {
// How long an ASN waits for a ready drive and the emergency module's first grant, ticks (2 s:
// CiA 402 drives are ready within a few hundred ms of start-up, docs/CAN.md).
constexpr std::uint64_t kServoWaitTicks = 200;
executor::GoToSettings with_robot(executor::GoToSettings s, const RobotConfig& robot) {
  s.wheel_base_mm = robot.wheel_base_mm;
  const auto cap = static_cast<std::int32_t>(std::min<std::uint32_t>(robot.max_speed_cm_s, 1000));
  s.max_drive_cm_s = std::min(s.max_drive_cm_s, cap);
  s.max_turn_cm_s = std::min(s.max_turn_cm_s, cap);
  return s;
}
}  // namespace

ExecutorModule::ExecutorModule(Blackboard& bb, hal::Drive& drive, const RobotConfig& robot,
                               const executor::GoToSettings& go_to)
    : drive_(drive),
      robot_(robot),
      go_to_(with_robot(go_to, robot)),
      command_(bb.motion_command.reader()),
      servo_(bb.servo_request.reader()),
      emergency_(bb.emergency.reader()),
      odometry_set_(bb.odometry_set.reader()),
      go_to_request_(bb.go_to.reader()),
      claim_(bb, MotionSource::go_to),
      posture_out_(bb.posture.writer()),
      go_to_requests_(bb.go_to_motion.writer()) {}

// Known state at start: servo off (wheels zero); requests from before the start are not
// replayed.
bool ExecutorModule::init(Kernel& k) {
  drive_.set_servo(false);
  servo_.copy();
  odometry_set_.copy();
  go_to_request_.copy();
  applied_seq_ = command_.generation();
  const executor::PostureUnits p = executor::to_posture(drive_.odometry());
  posture_out_.publish(Posture{p.x, p.y, p.theta, false, 0, 0, k.tick(), drive_.health(), applied_seq_});
  return true;
}

// The seed's close_execute: SERV OF, with the speeds zeroed first.
void ExecutorModule::close(Kernel&) {
  std::int32_t l = 0, r = 0;
  drive_.commanded(l, r);
  const bool was_on = drive_.servo();
  if (was_on) drive_.command_wheels(0, 0);
  drive_.set_servo(false);
  log::info("executor: drive stopped: zero speed (was {} {} cm/s), servo off (was {})", l, r, was_on ? "on" : "off");
}

// A command is applied once (by its generation), except "stop", which is enforced every activation: the
// servo stays off whatever else happens. Before the emergency module has published, nothing is
// granted (the default command is a stop).
void ExecutorModule::apply_command(bool drive_ok) {
  const MotionCommand& c = command_.peek();
  if (c.stop || !command_.advertised()) {
    if (drive_.servo()) drive_.set_servo(false);
    applied_seq_ = command_.generation();
    return;
  }
  if (command_.generation() == applied_seq_) return;
  applied_seq_ = command_.generation();
  if (c.left != 0 || c.right != 0) {
    if (!drive_ok) return;
    if (!drive_.servo()) drive_.set_servo(true);
    drive_.command_wheels(c.left, c.right);
  } else if (drive_.servo()) {
    drive_.command_wheels(0, 0);
  }
}

void ExecutorModule::end_go_to(Kernel& k, bool publish_stop) {
  if (!go_to_.active()) return;
  go_to_.cancel();
  if (publish_stop) go_to_requests_.send(k, false, 0, 0);
}

// The arbiter decides: a new run for the go-to (AW) starts it; the operator or an emergency
// taking the robot ends it. Then one control step per tick whatever the number of activations.
void ExecutorModule::serve_go_to(Kernel& k, const executor::PostureUnits& now) {
  const std::uint64_t tick = k.tick();
  if (claim_.granted()) {
    go_to_requests_.begin();
    const GoToRequest g = go_to_request_.copy();
    go_to_.start(executor::PostureUnits{g.x, g.y, g.theta});
    log::info("executor: go to {} {} {}", g.x, g.y, g.theta);
  } else if (go_to_.active()) {
    const ModeReason why = claim_.ended();
    if (why != ModeReason::none) {
      log::info("executor: go-to ended by {}", why == ModeReason::emergency ? "an emergency" : why == ModeReason::protective ? "a protective stop" : "the operator");
      end_go_to(k, false);
    }
  }
  if (go_to_request_.updated() && !go_to_request_.copy().active) end_go_to(k, true);  // a cancel
  if (!go_to_.active() || tick == last_go_to_tick_) return;
  last_go_to_tick_ = tick;
  const executor::WheelSpeeds w = go_to_.step(now);
  go_to_requests_.send(k, true, w.left, w.right);
  if (!go_to_.active()) log::info("executor: go-to reached {} {} {}", now.x, now.y, now.theta);
}

// One activation, in the seed's order: odometry, servo change, motion; then AC and the go-to.
void ExecutorModule::run(Kernel& k) {
  const std::uint64_t tick = k.tick();
  const hal::DriveHealth health = drive_.health();
  const bool drive_ok = health == hal::DriveHealth::ok;
  if (!drive_ok && drive_.servo()) drive_.set_servo(false);  // local reaction; emergency latches

  // Why an ASN waits: on CAN the drives take a few hundred ms to reach "ready" after start-up
  // (meanwhile the emergency module inhibits: a condition at rest), and an operator's ASN in that
  // time was acknowledged and then lost (the deploy rehearsal's check, docs/INSTALL.md). It waits
  // kServoWaitTicks at most for a ready drive and a grant; a trip, a latch or ASF drops it, so
  // nothing switches on by itself after an emergency.
  if (servo_.updated()) {
    const ServoRequest s = servo_.copy();
    servo_pending_ = s.on;
    servo_asked_tick_ = tick;
    servo_asked_trips_ = emergency_.peek().trips;
    if (!s.on) drive_.set_servo(false);  // (any AS also ends a go-to: the arbiter's table)
  }
  if (servo_pending_) {
    const MotionCommand& c = command_.peek();
    const EmergencyState& e = emergency_.peek();
    if (command_.advertised() && !c.stop && drive_ok) {
      drive_.set_servo(true);
      servo_pending_ = false;
    } else if (e.latched || e.trips != servo_asked_trips_ || tick - servo_asked_tick_ > kServoWaitTicks) {
      servo_pending_ = false;
      log::info("executor: servo on dropped ({})", tick - servo_asked_tick_ > kServoWaitTicks ? "drive not ready" : "an emergency");
    }
  }
  apply_command(drive_ok);

  if (odometry_set_.updated()) {
    const OdometrySet o = odometry_set_.copy();
    drive_.set_odometry(executor::to_odometry(executor::PostureUnits{o.x, o.y, o.theta}));
    odometry_seq_ = odometry_set_.generation();
    end_go_to(k, true);  // the target was in the old frame
  }
  const executor::PostureUnits now = executor::to_posture(drive_.odometry());
  serve_go_to(k, now);

  Posture p;
  p.x = now.x;
  p.y = now.y;
  p.theta = now.theta;
  p.servo = drive_.servo();
  drive_.commanded(p.left, p.right);
  p.tick = tick;
  p.drive_health = health;
  p.command_seq = applied_seq_;
  p.odometry_seq = odometry_seq_;
  posture_out_.publish(p);
}

}  // namespace robuter

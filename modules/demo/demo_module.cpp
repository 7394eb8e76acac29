// SPDX-License-Identifier: GPL-3.0-or-later
// Demonstration glue: settings, one course step per activation, requests and status.
#include "modules/demo/demo_module.hpp"

#include "kernel/kernel.hpp"
#include "kernel/log.hpp"

namespace robuter {

namespace {
demo::CourseSettings course_settings(const DemoConfig& c, const robot::RobotModel& robot) {
  demo::CourseSettings s;
  s.distx_mm = c.distx_mm;
  s.disty_mm = c.disty_mm;
  s.raio_mm = c.raio_mm;
  s.straight_mm = c.straight_mm;
  s.lane_mm = c.lane_mm;
  s.speed_cm_s = static_cast<std::int32_t>(c.speed_cm_s);
  s.slow_cm_s = static_cast<std::int32_t>(c.slow_cm_s);
  s.align_cm_s = static_cast<std::int32_t>(c.align_cm_s);
  s.sensor_a = static_cast<int>(c.sensor_a);
  s.sensor_b = static_cast<int>(c.sensor_b);
  s.front_sensor = static_cast<int>(c.front_sensor);
  s.align_tolerance_mm = c.align_tolerance_mm;
  s.calibration_readings = static_cast<int>(c.calibration_readings);
  s.laps = c.laps;
  s.wheel_base_mm = robot::mm_u(robot.wheels.base);
  s.calibration_timeout_ticks = c.calibration_timeout_ticks;
  return s;
}
}  // namespace

DemoModule::DemoModule(Blackboard& bb, const DemoConfig& cfg, const robot::RobotModel& robot)
    : ModeProcess(bb, MotionSource::demo, bb.demo_motion.writer(), bb.demo_status.writer()),
      course_(course_settings(cfg, robot)),
      posture_(bb.posture.reader()),
      ranges_(bb.ranges.reader()),
      emergency_state_(bb.emergency.reader()) {}

// The run of [demo] enabled is handed out by the emergency module's init, before this one: the
// course is running from the first tick.
bool DemoModule::init(Kernel& k) {
  DemoStatus s;
  s.tick = k.tick();
  if (begun()) {
    begin();
    s.state = ModeState::running;
  }
  status_out_.publish(s);
  return true;
}

void DemoModule::begin() {
  course_.start();
  running_ = true;
  log::info("demo: course started");
}

void DemoModule::run(Kernel& k) {
  const std::uint64_t tick = k.tick();
  if (begun()) {
    begin();
  } else if (running_) {
    const ModeReason why = claim_.ended();
    if (why != ModeReason::none) {
      course_.stop();
      running_ = false;
      log::info("demo: ended ({})", word(why));  // the reason XD reports
      demo::CourseOutput last;
      last.phase = demo::Phase::done;
      last.lap = status_out_.current().laps;
      report(last, ModeState::failed, why, tick);
      return;
    }
  }
  if (!running_) return;
  const EmergencyState& e = emergency_state_.peek();
  const Posture& p = posture_.peek();
  demo::CourseInputs in;
  in.tick = tick;
  in.pose = SectorPose{p.x, p.y, p.theta};
  in.ranges = &ranges_.peek();
  in.emergency = e.latched || e.cause != EmergencyCause::none;
  const demo::CourseOutput o = course_.step(in);
  requests_.send(k, o.request, o.left, o.right);
  ModeState st = ModeState::running;
  ModeReason why = ModeReason::none;
  if (o.phase == demo::Phase::done) {
    // Stopped before its laps were driven: the firmware is shutting down (close()).
    const bool all = course_.settings().laps > 0 && o.lap >= course_.settings().laps;
    st = all ? ModeState::finished : ModeState::failed;
    why = all ? ModeReason::none : ModeReason::shutdown;
  } else if (o.phase == demo::Phase::failed) {
    st = ModeState::failed;
    why = ModeReason::no_landmark;
  }
  if (st != ModeState::running) running_ = false;
  report(o, st, why, tick);
}

void DemoModule::report(const demo::CourseOutput& o, ModeState st, ModeReason why, std::uint64_t tick) {
  const DemoStatus& cur = status_out_.current();
  if (cur.phase == o.phase && cur.laps == o.lap && cur.state == st && cur.reason == why) return;
  if (st == ModeState::failed && cur.state != ModeState::failed && why == ModeReason::no_landmark)
    log::warn("demo: stopped in lap {} (calibration boxes not found)", o.lap + 1);
  DemoStatus s = cur;
  s.state = st;
  s.reason = why;
  s.phase = o.phase;
  s.laps = o.lap;
  s.side_mm = static_cast<std::int32_t>(course_.last_side_mm());
  s.radius_mm = static_cast<std::int32_t>(course_.last_radius_mm());
  if (o.lap_ended) s.lap_tick = tick;
  s.tick = tick;
  status_out_.publish(s);
  if (o.lap_ended)
    log::info("demo: lap {} done (side reading {:.0f} mm, calibration half-circle {:.0f} mm)", o.lap, course_.last_side_mm(),
              course_.last_radius_mm());
}

void DemoModule::close(Kernel& k) {
  if (!running_) return;
  course_.stop();
  run(k);
}

}  // namespace robuter

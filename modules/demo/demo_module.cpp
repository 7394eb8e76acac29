// SPDX-License-Identifier: GPL-3.0-or-later
// Demonstration glue: settings, one course step per activation, requests and status.
#include "modules/demo/demo_module.hpp"

#include "kernel/kernel.hpp"
#include "kernel/log.hpp"

namespace robuter {

namespace {
demo::CourseSettings course_settings(const Config& c) {
  demo::CourseSettings s;
  s.distx_mm = c.demo.distx_mm;
  s.disty_mm = c.demo.disty_mm;
  s.raio_mm = c.demo.raio_mm;
  s.straight_mm = c.demo.straight_mm;
  s.lane_mm = c.demo.lane_mm;
  s.speed_cm_s = static_cast<std::int32_t>(c.demo.speed_cm_s);
  s.slow_cm_s = static_cast<std::int32_t>(c.demo.slow_cm_s);
  s.align_cm_s = static_cast<std::int32_t>(c.demo.align_cm_s);
  s.sensor_a = static_cast<int>(c.demo.sensor_a);
  s.sensor_b = static_cast<int>(c.demo.sensor_b);
  s.front_sensor = static_cast<int>(c.demo.front_sensor);
  s.align_tolerance_mm = c.demo.align_tolerance_mm;
  static_assert(demo::kMaxCalibrationReadings == 9, "kernel/config.cpp bounds demo.calibration_readings by 9");
  s.calibration_readings = static_cast<int>(c.demo.calibration_readings);
  s.laps = c.demo.laps;
  s.wheel_base_mm = c.robot.wheel_base_mm;
  s.calibration_timeout_ticks = c.demo.calibration_timeout_ticks;
  return s;
}
}  // namespace

DemoModule::DemoModule(Blackboard& bb, const Config& cfg)
    : course_(course_settings(cfg)),
      claim_(bb, MotionSource::demo),
      posture_(bb.posture.reader()),
      ranges_(bb.ranges.reader()),
      emergency_state_(bb.emergency.reader()),
      motion_out_(bb.demo_motion.writer()),
      status_out_(bb.demo_status.writer()) {}

// The run of [demo] enabled is handed out by the emergency module's init, before this one: the
// course is running from the first tick.
bool DemoModule::init(Kernel& k) {
  DemoStatus s;
  s.tick = k.tick();
  if (claim_.granted()) {
    course_.start();
    running_ = true;
    sent_stop_ = false;
    s.state = ModeState::running;
    log::info("demo: course started");
  }
  status_out_.publish(s);
  return true;
}

void DemoModule::run(Kernel& k) {
  const std::uint64_t tick = k.tick();
  if (claim_.granted()) {
    course_.start();
    running_ = true;
    sent_stop_ = false;
    log::info("demo: course started");
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
  if (o.request || !sent_stop_) {
    motion_out_.modify([&](MotionRequest& r) {
      r.left = o.request ? o.left : 0;
      r.right = o.request ? o.right : 0;
      ++r.seq;
      r.tick = in.tick;
    });
    if (!o.request) sent_stop_ = true;
    if (emergency_) k.trigger(emergency_);
  }
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

// SPDX-License-Identifier: GPL-3.0-or-later
// Door-crossing glue: runs handed by the arbiter, the detections wish, interruptions, requests, status.
#include "modules/doors/doors_module.hpp"

#include "kernel/kernel.hpp"
#include "kernel/log.hpp"
#include "modules/doors/crossing_settings.hpp"
#include "modules/emergency/emergency.hpp"

namespace robuter {

DoorsModule::DoorsModule(Blackboard& bb, const DoorsConfig& cfg, const robot::RobotModel& model,
                         const ptu::EchoGeometry& echoes, EmergencyModule* emergency)
    : crossing_(doors::crossing_settings(cfg, model, echoes)),
      crossing_mask_(static_cast<std::uint8_t>(cfg.emergency_mask & kDetectAll)),
      scan_(bb.pan_tilt_scan.reader()),
      ptu_(bb.pan_tilt_status.reader()),
      posture_(bb.posture.reader()),
      link_(bb.link_status.reader()),
      claim_(bb, MotionSource::doors),
      requests_(bb.doors_motion.writer()),
      status_out_(bb.doors_status.writer()),
      detections_out_(bb.doors_detections.writer()) {
  requests_.set_emergency(emergency);
}

// Why lower the mask: the seed's doors() sets emerg.on = BUMPER — the ring would see the door's
// edges under the safety distance and stop the robot in the doorway; the link may stay silent
// for the whole slow crossing. The wish stands; the emergency module decides when it holds.
bool DoorsModule::init(Kernel& k) {
  claim_.init();
  detections_out_.publish(DetectionRequest{true, crossing_mask_});
  status_out_.publish(ModeStatus{ModeState::off, ModeReason::none, 0, k.tick(), 0, 0, k.tick()});
  return true;
}

void DoorsModule::begin(std::uint64_t tick) {
  crossing_.start(tick);
  had_link_ = link_.peek().links_open > 0;
  requests_.begin();
  log::info("doors: crossing (emergency detections {} while in the door)", crossing_mask_);
}

void DoorsModule::run(Kernel& k) {
  const std::uint64_t tick = k.tick();
  if (claim_.granted()) {
    begin(tick);  // Ad, or the passage finder's hand-over
  } else if (crossing_.active()) {
    ModeReason why = claim_.ended();  // Af, the operator, an emergency
    if (why == ModeReason::none && had_link_ && link_.peek().links_open == 0) why = ModeReason::link_lost;
    if (why != ModeReason::none) crossing_.fail(why);
  }
  const Posture& p = posture_.peek();
  doors::CrossingInputs in;
  in.tick = tick;
  in.scan = &scan_.peek();
  in.pose = SectorPose{p.x, p.y, p.theta};
  in.scanner_failed = ptu_.peek().state == ModeState::failed;
  publish(k, crossing_.step(in));
}

// Every way out passes here with request = false: the zero request, then the mask.
void DoorsModule::publish(Kernel& k, const doors::CrossingOutput& o) {
  const std::uint64_t tick = k.tick();
  requests_.send(k, o.request, o.left, o.right);
  const ModeStatus& cur = status_out_.current();
  if (cur.state == o.state && cur.reason == o.reason) return;
  ModeStatus s = cur;
  if (o.state == ModeState::starting) ++s.runs;
  s.state = o.state;
  s.reason = o.reason;
  s.since_tick = tick;
  s.duration_ticks = o.duration_ticks;
  s.tick = tick;
  status_out_.publish(s);
  if (o.state == ModeState::crossed) log::info("doors: door crossed in {} ticks", o.duration_ticks);
  else if (o.state == ModeState::failed) log::warn("doors: stopped after {} ticks (reason {})", o.duration_ticks, static_cast<int>(o.reason));
  else if (o.state == ModeState::waiting) log::info("doors: blocked on both sides, waiting for fresh readings");
}

void DoorsModule::close(Kernel& k) {
  if (crossing_.active()) {
    crossing_.fail(ModeReason::shutdown);
    publish(k, crossing_.step(doors::CrossingInputs{k.tick(), &scan_.peek(), {}, false}));
  }
}

}  // namespace robuter

// SPDX-License-Identifier: GPL-3.0-or-later
// Door-crossing glue: runs handed by the arbiter, the detections wish, interruptions, requests, status.
#include "modules/doors/doors_module.hpp"

#include "kernel/kernel.hpp"
#include "kernel/log.hpp"
#include "modules/doors/crossing_settings.hpp"
#include "modules/emergency/emergency.hpp"
#include "modules/mode_status.hpp"

namespace robuter {

DoorsModule::DoorsModule(Blackboard& bb, const DoorsConfig& cfg, const robot::RobotModel& model,
                         const ptu::EchoGeometry& echoes, EmergencyModule* emergency)
    : ScanMode(bb, MotionSource::doors, bb.doors_motion.writer(), bb.doors_status.writer(),
               doors::DoorCrossing(doors::crossing_settings(cfg, model, echoes))),
      crossing_mask_(static_cast<std::uint8_t>(cfg.emergency_mask & kDetectAll)),
      link_(bb.link_status.reader()),
      detections_out_(bb.doors_detections.writer()) {
  set_emergency(emergency);
}

// Why lower the mask: the seed's doors() sets emerg.on = BUMPER — the ring would see the door's
// edges under the safety distance and stop the robot in the doorway; the link may stay silent
// for the whole slow crossing. The wish stands; the emergency module decides when it holds.
bool DoorsModule::init(Kernel& k) {
  detections_out_.publish(DetectionRequest{true, crossing_mask_});
  return ScanMode::init(k);
}

void DoorsModule::begin(std::uint64_t tick) {
  logic_.start(tick);
  had_link_ = link_.peek().links_open > 0;
  log::info("doors: crossing (emergency detections {} while in the door)", crossing_mask_);
}

ModeReason DoorsModule::ended() const {
  const ModeReason why = ScanMode::ended();
  if (why == ModeReason::none && had_link_ && link_.peek().links_open == 0) return ModeReason::link_lost;
  return why;
}

// Every way out passes here with request = false: after the zero request, the status that gives
// the mask back (the emergency module grants it only while the crossing is in the door).
void DoorsModule::report(std::uint64_t tick, const doors::CrossingOutput& o) {
  const ModeStatus& cur = status_out_.current();
  if (cur.state == o.state && cur.reason == o.reason) return;
  ModeStatus s = moved_on(cur, o.state, o.reason, o.state == ModeState::starting, tick);
  s.since_tick = tick;  // a new reason in the same state restarts it too
  s.duration_ticks = o.duration_ticks;
  status_out_.publish(s);
  if (o.state == ModeState::crossed) log::info("doors: door crossed in {} ticks", o.duration_ticks);
  else if (o.state == ModeState::failed) log::warn("doors: stopped after {} ticks ({})", o.duration_ticks, word(o.reason));
  else if (o.state == ModeState::waiting) log::info("doors: blocked on both sides, waiting for fresh readings");
}

}  // namespace robuter

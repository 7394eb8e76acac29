// Door-crossing glue: Ad/Af and hand-over, the emergency mask, interruptions, requests, status.
#include "modules/doors/doors_module.hpp"

#include "kernel/kernel.hpp"
#include "kernel/log.hpp"
#include "modules/doors/crossing_settings.hpp"
#include "modules/emergency/emergency.hpp"

namespace robuter {

DoorsModule::DoorsModule(Blackboard& bb, const Config& cfg, EmergencyModule* emergency)
    : crossing_(doors::crossing_settings(cfg)),
      emergency_(emergency),
      crossing_mask_(static_cast<std::uint8_t>(cfg.doors.emergency_mask & 7u)),
      hand_over_(cfg.gate.hand_over),
      modes_(bb.modes.reader()),
      scan_(bb.pan_tilt_scan.reader()),
      ptu_(bb.pan_tilt_status.reader()),
      gate_(bb.gate_status.reader()),
      posture_(bb.posture.reader()),
      link_(bb.link_status.reader()),
      claim_(bb, MotionSource::doors),
      motion_out_(bb.doors_motion.writer()),
      status_out_(bb.doors_status.writer()) {}

bool DoorsModule::init(Kernel& k) {
  seen_modes_ = modes_.peek().doors_seq;
  gate_seen_ = gate_.peek().state;
  status_out_.publish(ModeStatus{ModeState::off, ModeReason::none, 0, k.tick(), 0, 0, k.tick()});
  return true;
}

// Why lower the mask: the seed's doors() sets emerg.on = BUMPER — the ring would see the door's
// edges under the safety distance and stop the robot in the doorway; the link may stay silent
// for the whole slow crossing.
void DoorsModule::begin(std::uint64_t tick) {
  crossing_.start(tick);
  claim_.begin();
  had_link_ = link_.peek().links_open > 0;
  sent_stop_ = false;
  if (emergency_ && !lowered_) {
    saved_mask_ = emergency_->enabled();
    emergency_->set_enabled(crossing_mask_);
    lowered_ = true;
  }
  log::info("doors: crossing (emergency detections {} while crossing, {} before)", crossing_mask_, saved_mask_);
}

void DoorsModule::restore_mask() {
  if (!lowered_) return;
  if (emergency_) emergency_->set_enabled(saved_mask_);
  lowered_ = false;
  log::info("doors: emergency detections back to {}", saved_mask_);
}

void DoorsModule::run(Kernel& k) {
  const std::uint64_t tick = k.tick();
  const ModeRequest& m = modes_.peek();
  if (m.doors_seq != seen_modes_) {
    seen_modes_ = m.doors_seq;
    if (m.doors && !crossing_.active()) begin(tick);             // Ad
    else if (!m.doors && crossing_.active()) crossing_.fail(ModeReason::cancelled);  // Af
  }
  const ModeState gs = gate_.peek().state;
  if (hand_over_ && gs == ModeState::aligned && gate_seen_ != ModeState::aligned && !crossing_.active()) begin(tick);
  gate_seen_ = gs;
  if (crossing_.active()) {
    ModeReason why = claim_.interrupted();
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
  const bool ending = !o.request && !sent_stop_;
  if (o.request || (ending && o.reason != ModeReason::operator_motion)) {
    motion_out_.modify([&](MotionRequest& r) {
      r.left = o.request ? o.left : 0;
      r.right = o.request ? o.right : 0;
      ++r.seq;
      r.tick = tick;
    });
  }
  if (ending) {
    sent_stop_ = true;
    restore_mask();
  }
  if ((o.request || ending) && emergency_) k.trigger(emergency_);
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
  restore_mask();
}

}  // namespace robuter

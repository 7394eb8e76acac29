// SPDX-License-Identifier: GPL-3.0-or-later
// Passage-finder glue: runs handed by the arbiter (AG) and their end, requests and status.
#include "modules/gate/gate_module.hpp"

#include "kernel/kernel.hpp"
#include "kernel/log.hpp"
#include "modules/gate/gate_settings.hpp"

namespace robuter {

GateModule::GateModule(Blackboard& bb, const GateConfig& cfg, const robot::RobotModel& model,
                       const ptu::EchoGeometry& echoes)
    : logic_(gate::gate_settings(cfg, model, echoes)),
      scan_(bb.pan_tilt_scan.reader()),
      ptu_(bb.pan_tilt_status.reader()),
      posture_(bb.posture.reader()),
      claim_(bb, MotionSource::gate),
      requests_(bb.gate_motion.writer()),
      status_out_(bb.gate_status.writer()) {}

bool GateModule::init(Kernel& k) {
  claim_.init();
  status_out_.publish(ModeStatus{ModeState::off, ModeReason::none, 0, k.tick(), 0, 0, k.tick()});
  return true;
}

void GateModule::run(Kernel& k) {
  const std::uint64_t tick = k.tick();
  if (claim_.granted()) {  // AG (a second AG restarts the search)
    logic_.start(tick);
    started_ = tick;
    requests_.begin();
    log::info("gate: searching for a passage");
  } else if (logic_.active()) {  // AT, the operator, an emergency
    const ModeReason why = claim_.ended();
    if (why != ModeReason::none) logic_.fail(why);
  }
  const Posture& p = posture_.peek();
  gate::GateInputs in;
  in.tick = tick;
  in.scan = &scan_.peek();
  in.pose = SectorPose{p.x, p.y, p.theta};
  in.scanner_failed = ptu_.peek().state == ModeState::failed;
  publish(k, logic_.step(in));
}

void GateModule::publish(Kernel& k, const gate::GateOutput& o) {
  const std::uint64_t tick = k.tick();
  requests_.send(k, o.request, o.left, o.right);
  const ModeStatus& cur = status_out_.current();
  if (cur.state == o.state && cur.reason == o.reason && cur.width_mm == o.width_mm) return;
  ModeStatus s = cur;
  if (o.state == ModeState::searching && cur.state != ModeState::searching && cur.state != ModeState::moving) ++s.runs;
  s.state = o.state;
  s.reason = o.reason;
  s.width_mm = o.width_mm;
  if (cur.state != o.state) s.since_tick = tick;
  s.duration_ticks = static_cast<std::uint32_t>(tick - started_);
  s.tick = tick;
  status_out_.publish(s);
  if (cur.state == o.state) return;
  const gate::GateLogic& g = logic_;
  if (o.state == ModeState::aligned)
    log::info("gate: aligned after {} manoeuvres: lateral {:.0f} mm, heading {:.1f}°, front {:.0f} mm from the passage, width {} mm",
              g.manoeuvres(), g.lateral_error_mm(), g.heading_error_deg(), g.front_distance_mm(), o.width_mm);
  else if (o.state == ModeState::moving)
    log::info("gate: manoeuvre {}: lateral {:.0f} mm, heading {:.1f}°, front {:.0f} mm, width {} mm", g.manoeuvres(),
              g.lateral_error_mm(), g.heading_error_deg(), g.front_distance_mm(), o.width_mm);
  else if (o.state == ModeState::failed)
    log::warn("gate: failed ({})", static_cast<int>(o.reason));
}

void GateModule::close(Kernel& k) {
  if (logic_.active()) {
    logic_.fail(ModeReason::shutdown);
    publish(k, logic_.step(gate::GateInputs{k.tick(), &scan_.peek(), {}, false}));
  }
}

}  // namespace robuter

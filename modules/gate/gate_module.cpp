// SPDX-License-Identifier: GPL-3.0-or-later
// Passage-finder glue: runs handed by the arbiter (AG) and their end, requests and status.
#include "modules/gate/gate_module.hpp"

#include "kernel/kernel.hpp"
#include "kernel/log.hpp"
#include "modules/gate/gate_settings.hpp"
#include "modules/mode_status.hpp"

namespace robuter {

GateModule::GateModule(Blackboard& bb, const GateConfig& cfg, const robot::RobotModel& model,
                       const ptu::EchoGeometry& echoes)
    : ScanMode(bb, MotionSource::gate, bb.gate_motion.writer(), bb.gate_status.writer(),
               gate::GateLogic(gate::gate_settings(cfg, model, echoes))) {}

void GateModule::begin(std::uint64_t tick) {
  logic_.start(tick);
  started_ = tick;
  log::info("gate: searching for a passage");
}

void GateModule::report(std::uint64_t tick, const gate::GateOutput& o) {
  const ModeStatus& cur = status_out_.current();  // the topic's value: publish() below replaces it
  if (cur.state == o.state && cur.reason == o.reason && cur.width_mm == o.width_mm) return;
  const ModeState was = cur.state;
  const bool new_run = o.state == ModeState::searching && was != ModeState::searching && was != ModeState::moving;
  ModeStatus s = moved_on(cur, o.state, o.reason, new_run, tick);
  s.width_mm = o.width_mm;
  s.duration_ticks = static_cast<std::uint32_t>(tick - started_);
  status_out_.publish(s);
  if (was == o.state) return;
  const gate::GateLogic& g = logic_;
  if (o.state == ModeState::aligned)
    log::info("gate: aligned after {} manoeuvres: lateral {:.0f} mm, heading {:.1f}°, front {:.0f} mm from the passage, width {} mm",
              g.manoeuvres(), g.lateral_error_mm(), g.heading_error_deg(), g.front_distance_mm(), o.width_mm);
  else if (o.state == ModeState::moving)
    log::info("gate: manoeuvre {}: lateral {:.0f} mm, heading {:.1f}°, front {:.0f} mm, width {} mm", g.manoeuvres(),
              g.lateral_error_mm(), g.heading_error_deg(), g.front_distance_mm(), o.width_mm);
  else if (o.state == ModeState::failed)
    log::warn("gate: failed ({})", word(o.reason));
}

}  // namespace robuter

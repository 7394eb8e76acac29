// SPDX-License-Identifier: GPL-3.0-or-later
// Ultrasonic process glue: settings in, one scanner step, ranges and timing out.
#include "modules/us/ultrasonic.hpp"

#include "kernel/kernel.hpp"
#include "kernel/log.hpp"

namespace robuter {

UltrasonicModule::UltrasonicModule(Blackboard& bb, hal::SonarRing& ring, const SonarConfig& cfg)
    : ring_(ring),
      cfg_(cfg),
      settings_(bb.us_settings.reader()),
      selection_(bb.sonar_selection.reader()),
      ranges_out_(bb.ranges.writer()),
      timing_out_(bb.us_timing.writer()),
      watch_(cfg.schedule != "seed") {}

// The first scan configures the ring; nothing else to prepare.
bool UltrasonicModule::init(Kernel&) {
  log::info("us: time-out {} ms, sound {} m/s, node delay {} ticks, {} schedule (moving time-out {} ms)",
            cfg_.timeout_ms, cfg_.sound_speed_m_s, cfg_.node_delay_ticks, watch_ ? "watch" : "seed",
            cfg_.moving_timeout_ms);
  return true;
}

// The operator's settings once published, the configuration before; time-outs rounded up to
// whole ticks because a node cannot be read before its echoes are in. A priority firing listens
// as far as the emergency module needs (2 · listen_mm / c, in whole ms).
us::ScanRequest UltrasonicModule::request(Nanos tick_ns) const {
  us::ScanRequest r;
  const SonarSelection& sel = selection_.peek();
  r.active = sel.active;
  r.sound_speed_m_s = cfg_.sound_speed_m_s;
  if (settings_.advertised()) {
    r.node_delay_ticks = settings_.peek().node_delay_ticks;
    r.timeout_ms = settings_.peek().timeout_ms;
  } else {
    r.node_delay_ticks = cfg_.node_delay_ticks;
    r.timeout_ms = cfg_.timeout_ms;
  }
  const auto ticks = [tick_ns](std::uint32_t ms) {
    const Nanos ns = static_cast<Nanos>(ms) * kNanosPerMilli;
    return tick_ns > 0 ? static_cast<std::uint32_t>((ns + tick_ns - 1) / tick_ns) : 1u;
  };
  r.timeout_ticks = ticks(r.timeout_ms);
  r.watch = watch_;
  r.priority = sel.priority;
  if (sel.listen_mm > 0 && r.sound_speed_m_s > 0) {
    r.priority_timeout_ms = (2 * sel.listen_mm + r.sound_speed_m_s - 1) / r.sound_speed_m_s;
    r.priority_timeout_ticks = ticks(r.priority_timeout_ms);
  }
  if (cfg_.moving_timeout_ms > 0) {
    r.moving_timeout_ms = cfg_.moving_timeout_ms;
    r.moving_timeout_ticks = ticks(r.moving_timeout_ms);
  }
  return r;
}

// One step of the firing sequence; new ranges are published and judged at once.
void UltrasonicModule::run(Kernel& k) {
  if (scanner_.step(k.tick(), ring_, request(k.tick_ns()))) {
    ranges_out_.publish(scanner_.ranges());
    if (emergency_) k.trigger(emergency_);
  }
  const UltrasonicTiming t{scanner_.stats().mean_node(), scanner_.stats().mean_scan()};
  const UltrasonicTiming& cur = timing_out_.current();
  if (t.mean_node_ticks != cur.mean_node_ticks || t.mean_scan_ticks != cur.mean_scan_ticks) timing_out_.publish(t);
  if (scanner_.lost_reads() != lost_logged_) {
    lost_logged_ = scanner_.lost_reads();
    log::warn("us: a node's readings were lost ({} so far); its sensors read 0 until the next scan", lost_logged_);
  }
}

}  // namespace robuter

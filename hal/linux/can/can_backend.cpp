// SPDX-License-Identifier: GPL-3.0-or-later
// CAN backend process: frame dispatch, periodic supervision and SYNC, transition logs.
#include "hal/linux/can/can_backend.hpp"

#include "hal/linux/can/cia402.hpp"
#include "kernel/kernel.hpp"
#include "kernel/log.hpp"
#include "kernel/signals.hpp"

namespace robuter::hal::can {

namespace {
std::int64_t micros(Kernel& k) { return k.now() / 1000; }
}  // namespace

CanBackend::CanBackend(FrameTransport& bus, const CanConfig& cfg, std::uint32_t wheel_base_mm, bool with_drive,
                       bool with_sonar)
    : bus_(bus),
      host_node_(static_cast<std::uint8_t>(cfg.host_node)),
      host_period_us_(static_cast<std::int64_t>(cfg.host_heartbeat_ms) * 1000) {
  if (with_drive) drive_.emplace(bus, cfg, wheel_base_mm);
  if (with_sonar) ring_.emplace(bus, static_cast<std::uint8_t>(cfg.sonar_node_base), cfg.heartbeat_timeout_ms);
  quick_stop_[0] = cia402::rpdo1(static_cast<std::uint8_t>(cfg.left_node), cia402::kCwQuickStop, 0);
  quick_stop_[1] = cia402::rpdo1(static_cast<std::uint8_t>(cfg.right_node), cia402::kCwQuickStop, 0);
}

CanBackend::~CanBackend() {
  if (hooked_) signals::remove_fatal_hooks(this);
}

void CanBackend::quick_stop_from_signal(void* self) {
  const auto* b = static_cast<const CanBackend*>(self);
  for (const can_frame& f : b->quick_stop_) b->bus_.send_from_signal(f);
}

void CanBackend::start(std::int64_t now_us) {
  if (drive_) drive_->start(now_us);
  if (ring_) ring_->start(now_us);
}

// The socket is polled every tick, not watched: the drives answer the SYNC within the tick, and
// an event activation between ticks would either send another SYNC (a feedback loop with the
// drives' answers) or leave the frames for the modules that only run on their own periods anyway.
bool CanBackend::init(Kernel& k) {
  start(micros(k));
  if (drive_ && !hooked_)
    hooked_ = signals::add_fatal_hook(quick_stop_from_signal, this, "drives sent quick stop (CAN RPDO1 controlword 0x0002)");
  log::info("can: {} up{}{}", bus_.name(), drive_ ? ", drives" : "", ring_ ? ", ultrasonic nodes" : "");
  return true;
}


// Runs first in its tick: "on time" covers every row up to the previous tick.
void CanBackend::run(Kernel& k) {
  const bool on_time = k.rows_on_time() && k.late_events() == late_seen_;
  late_seen_ = k.late_events();
  service(micros(k), on_time);
}

void CanBackend::service(std::int64_t now, bool loop_on_time) {
  can_frame f;
  for (int i = 0; i < kMaxFramesPerRun && bus_.receive(f); ++i) {
    const bool taken = (drive_ && drive_->on_frame(f, now)) || (ring_ && ring_->on_frame(f, now));
    if (!taken) ++unknown_;
  }
  if (drive_) {
    drive_->poll(now);
    bus_.send(cia402::sync());
  }
  if (ring_) ring_->poll(now);
  // The host's heartbeat, which the drives consume (0x1016): only from here, the periodic path,
  // and only while the loop keeps its schedule, so a hung or late loop is a lost heartbeat.
  if (loop_on_time && (last_host_heartbeat_us_ < 0 || now - last_host_heartbeat_us_ >= host_period_us_)) {
    if (bus_.send(cia402::heartbeat(host_node_, cia402::NmtState::operational))) ++host_heartbeats_;
    last_host_heartbeat_us_ = now;
  }
  bus_.flush();
  log_transitions();
}

void CanBackend::log_transitions() {
  const BusState bus = bus_.bus_state();
  if (bus != last_bus_) {
    if (bus == BusState::passive || bus == BusState::off) log::warn("can: {}: {}", bus_.name(), word(bus));
    else log::info("can: {}: {}", bus_.name(), word(bus));
    last_bus_ = bus;
  }
  if (!drive_) return;
  const DriveHealth h = drive_->health();
  if (h != last_health_) {
    if (h == DriveHealth::ok) {
      log::info("can: drives ready (nodes {} and {})", drive_->left().settings().node, drive_->right().settings().node);
    } else {
      log::warn("can: drives {}: left node {} {} (EMCY {:04X}), right node {} {} (EMCY {:04X})", word(h),
                drive_->left().settings().node, word(drive_->left_fault()), drive_->left().status().emcy_code,
                drive_->right().settings().node, word(drive_->right_fault()),
                drive_->right().status().emcy_code);
    }
    last_health_ = h;
  }
}

}  // namespace robuter::hal::can

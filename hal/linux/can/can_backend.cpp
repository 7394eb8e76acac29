// CAN backend process: frame dispatch, periodic supervision and SYNC, transition logs.
#include "hal/linux/can/can_backend.hpp"

#include "hal/linux/can/cia402.hpp"
#include "kernel/kernel.hpp"
#include "kernel/log.hpp"

namespace robuter::hal::can {

namespace {
const char* health_name(DriveHealth h) {
  switch (h) {
    case DriveHealth::ok: return "ok";
    case DriveHealth::fault: return "fault";
    case DriveHealth::silent: return "heartbeat lost";
    case DriveHealth::bus_passive: return "bus error-passive";
    case DriveHealth::bus_off: return "bus-off";
  }
  return "?";
}
const char* fault_name(DriveFault f) {
  switch (f) {
    case DriveFault::none: return "ok";
    case DriveFault::heartbeat_lost: return "heartbeat lost";
    case DriveFault::fault: return "fault";
    case DriveFault::not_operational: return "not operational";
  }
  return "?";
}
std::int64_t micros(Kernel& k) { return k.now() / 1000; }
}  // namespace

CanBackend::CanBackend(FrameTransport& bus, const CanConfig& cfg, std::uint32_t wheel_base_mm, bool with_drive,
                       bool with_sonar)
    : bus_(bus) {
  if (with_drive) drive_.emplace(bus, cfg, wheel_base_mm);
  if (with_sonar) ring_.emplace(bus, static_cast<std::uint8_t>(cfg.sonar_node_base), cfg.heartbeat_timeout_ms);
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
  log::info("can: {} up{}{}", bus_.name(), drive_ ? ", drives" : "", ring_ ? ", ultrasonic nodes" : "");
  return true;
}


void CanBackend::run(Kernel& k) { service(micros(k)); }

void CanBackend::service(std::int64_t now) {
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
  log_transitions();
}

void CanBackend::log_transitions() {
  const BusState bus = bus_.bus_state();
  if (bus != last_bus_) {
    if (bus == BusState::passive || bus == BusState::off) log::warn("can: {}: {}", bus_.name(), bus_state_name(bus));
    else log::info("can: {}: {}", bus_.name(), bus_state_name(bus));
    last_bus_ = bus;
  }
  if (!drive_) return;
  const DriveHealth h = drive_->health();
  if (h != last_health_) {
    if (h == DriveHealth::ok) {
      log::info("can: drives ready (nodes {} and {})", drive_->left().settings().node, drive_->right().settings().node);
    } else {
      log::warn("can: drives {}: left node {} {} (EMCY {:04X}), right node {} {} (EMCY {:04X})", health_name(h),
                drive_->left().settings().node, fault_name(drive_->left_fault()), drive_->left().status().emcy_code,
                drive_->right().settings().node, fault_name(drive_->right_fault()),
                drive_->right().status().emcy_code);
    }
    last_health_ = h;
  }
}

}  // namespace robuter::hal::can

// SPDX-License-Identifier: GPL-3.0-or-later
// The kernel process that runs the CAN bus: takes frames, supervises drives and sonar nodes, sends RPDOs and SYNC.
#pragma once

#include <array>
#include <memory>
#include <optional>

#include "hal/linux/can/can_drive.hpp"
#include "hal/linux/can/can_sonar_ring.hpp"
#include "hal/linux/can/frame_transport.hpp"
#include "kernel/config.hpp"
#include "kernel/process.hpp"

namespace robuter::hal::can {

// Runs every tick before the modules that use the drive and the ring (process row "can"):
// every waiting frame (bounded) goes to the drive pair or the ring, then timers, RPDO1s and one
// SYNC that makes the drives answer with TPDO1/TPDO2 for the next tick. Logs bus-state and
// drive-health transitions.
class CanBackend final : public Process {
 public:
  static constexpr int kMaxFramesPerRun = 128;  // frames taken per activation (bounded work)

  // `with_drive` / `with_sonar`: which HAL parts run on this bus.
  CanBackend(FrameTransport& bus, const CanConfig& cfg, std::uint32_t wheel_base_mm, bool with_drive,
             bool with_sonar);
  ~CanBackend() override;
  CanDrive* drive() { return drive_ ? &*drive_ : nullptr; }
  CanSonarRing* ring() { return ring_ ? &*ring_ : nullptr; }
  FrameTransport& bus() { return bus_; }
  std::uint64_t unknown_frames() const { return unknown_; }

  // Bring-up of drives and nodes from `now_us` (init does it at the kernel's time).
  void start(std::int64_t now_us);
  // One activation at `now_us` (run() does it at the kernel's time; tests call it directly).
  // `loop_on_time`: every process row ran at its due tick since the last activation — only
  // then does the host's heartbeat go out (the drives' watchdog, docs/SAFETY.md).
  void service(std::int64_t now_us, bool loop_on_time = true);
  // Host heartbeats sent, count.
  std::uint64_t host_heartbeats() const { return host_heartbeats_; }

  bool init(Kernel& k) override;
  void run(Kernel& k) override;

  // The fatal-signal hook (kernel/signals.hpp): both drives get a prepared RPDO1 with the quick
  // stop controlword and zero velocity, through the transport's async-signal-safe send.
  static void quick_stop_from_signal(void* self);

 private:
  // Logs what changed since the last activation (transitions only).
  void log_transitions();

  FrameTransport& bus_;
  std::optional<CanDrive> drive_;
  std::optional<CanSonarRing> ring_;
  BusState last_bus_ = BusState::active;        // for transition logs
  DriveHealth last_health_ = DriveHealth::silent;
  std::uint64_t unknown_ = 0;                    // frames no one took, count
  std::uint8_t host_node_;                       // node id of the host's heartbeat
  std::int64_t host_period_us_;                  // host heartbeat period, µs
  std::int64_t last_host_heartbeat_us_ = -1;     // when it last went out, µs (-1: never)
  std::uint64_t host_heartbeats_ = 0;            // sent, count
  std::uint64_t late_seen_ = 0;                  // Kernel::late_events() at the last activation
  std::array<can_frame, 2> quick_stop_{};        // prepared RPDO1s for the fatal-signal hook
  bool hooked_ = false;                          // the fatal hook is registered
};

}  // namespace robuter::hal::can

// The kernel process that runs the CAN bus: takes frames, supervises drives and sonar nodes, sends RPDOs and SYNC.
#pragma once

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
  CanDrive* drive() { return drive_ ? &*drive_ : nullptr; }
  CanSonarRing* ring() { return ring_ ? &*ring_ : nullptr; }
  FrameTransport& bus() { return bus_; }
  std::uint64_t unknown_frames() const { return unknown_; }

  // Bring-up of drives and nodes from `now_us` (init does it at the kernel's time).
  void start(std::int64_t now_us);
  // One activation at `now_us` (run() does it at the kernel's time; tests call it directly).
  void service(std::int64_t now_us);

  bool init(Kernel& k) override;
  void run(Kernel& k) override;

 private:
  // Logs what changed since the last activation (transitions only).
  void log_transitions();

  FrameTransport& bus_;
  std::optional<CanDrive> drive_;
  std::optional<CanSonarRing> ring_;
  BusState last_bus_ = BusState::active;        // for transition logs
  DriveHealth last_health_ = DriveHealth::silent;
  std::uint64_t unknown_ = 0;                    // frames no one took, count
};

}  // namespace robuter::hal::can

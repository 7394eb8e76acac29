// SPDX-License-Identifier: GPL-3.0-or-later
// Host side of one CiA 402 drive: bring-up (SDO, NMT start), controlword stepping, feedback, heartbeat and fault watch. Pure.
#pragma once

#include <linux/can.h>

#include <array>
#include <cstddef>
#include <cstdint>

#include "hal/linux/can/cia402.hpp"

namespace robuter::hal::can {

// Frames produced by one poll, sent by the caller (no allocation).
struct FrameBatch {
  static constexpr std::size_t kMax = 8;  // frames one poll may produce
  std::array<can_frame, kMax> frames{};   // the frames, in sending order
  std::size_t count = 0;                  // frames used
  void push(const can_frame& f) {
    if (count < kMax) frames[count++] = f;
  }
};

// One drive's parameters (docs/CAN.md; [can] in the configuration).
struct DriveLinkSettings {
  std::uint8_t node = 1;                     // CANopen node id, 1..127
  std::uint16_t heartbeat_ms = 100;          // heartbeat producer time written to 0x1017, ms
  std::uint32_t heartbeat_timeout_ms = 350;  // no heartbeat for this long: the drive is lost, ms
  std::uint32_t sdo_timeout_ms = 100;        // an unanswered SDO write is sent again after this, ms
  std::uint32_t fault_reset_ms = 1000;       // a drive in fault gets a fault reset this often, ms
  std::uint8_t host_node = 127;              // node id of the host's own heartbeat (0x700 + id)
  std::uint16_t watchdog_ms = 0;             // consumer heartbeat time written to 0x1016:01, ms (0: not written)
};

// Where the bring-up is.
enum class LinkPhase : std::uint8_t {
  configure_mode,       // SDO write 0x6060 = 3 (profile velocity) sent, awaiting the answer
  configure_heartbeat,  // SDO write 0x1017 = heartbeat_ms sent, awaiting the answer
  configure_consumer,   // SDO write 0x1016:01 = host node, watchdog_ms sent (the drive watches the host)
  configure_abort,      // SDO write 0x6007 = 3 sent: quick stop when the host's heartbeat is lost
  starting,             // NMT start sent, awaiting an "operational" heartbeat
  running,              // PDOs flow: RPDO1 every poll, TPDO1/2 on SYNC
};

// What is wrong with the drive (none = usable), with the words the CAN backend's logs write.
#define ROBUTER_DRIVE_FAULTS(X)                                                                        \
  X(none, "ok")                                                                                        \
  X(heartbeat_lost, "heartbeat lost")   /* no heartbeat (or SDO answer) within the time-out */         \
  X(fault, "fault")                     /* statusword fault / fault reaction, an EMCY error, an SDO abort */ \
  X(not_operational, "not operational") /* heard, but bring-up not finished (or the node left "operational") */
enum class DriveFault : std::uint8_t { ROBUTER_DRIVE_FAULTS(ROBUTER_VOCAB_ENUMERATOR) };
ROBUTER_VOCABULARY(DriveFault, ROBUTER_DRIVE_FAULTS, "fault");

// The host's view of one drive.
struct DriveLinkStatus {
  LinkPhase phase = LinkPhase::configure_mode;                 // bring-up step
  cia402::State state = cia402::State::not_ready_to_switch_on; // from the last statusword
  std::uint16_t statusword = 0;     // last statusword (TPDO1)
  std::uint16_t controlword = 0;    // last controlword sent (RPDO1)
  std::int32_t velocity = 0;        // velocity actual value (TPDO1), increments/s
  std::int32_t position = 0;        // position actual value (TPDO2), increments
  bool position_valid = false;      // a TPDO2 arrived since the bring-up started
  std::uint32_t positions = 0;      // TPDO2 frames taken, count (odometry consumers compare)
  std::uint16_t emcy_code = 0;      // last EMCY error code (0: none or reset)
  bool emcy_active = false;         // an EMCY error not yet reset
  std::uint32_t sdo_abort = 0;      // abort code of a refused SDO write (0: none)
  std::uint32_t restarts = 0;       // bring-ups after the first (boot-up seen, heartbeat back), count
};

class DriveLink {
 public:
  explicit DriveLink(const DriveLinkSettings& s) : s_(s) {}
  const DriveLinkSettings& settings() const { return s_; }
  // Starts (or restarts) the bring-up at `now_us`: the next poll sends the first SDO write.
  void start(std::int64_t now_us);
  // Takes a frame from the bus; false when it is not this drive's.
  bool on_frame(const can_frame& f, std::int64_t now_us);
  // Time-driven work at `now_us`; appends what to send now. While running: one RPDO1 with the
  // next controlword toward `enable` and the target velocity (0 unless operation enabled).
  void poll(std::int64_t now_us, bool enable, std::int32_t target_velocity, FrameBatch& out);
  // The worst problem at `now_us`.
  DriveFault fault(std::int64_t now_us) const;
  // Operation enabled and running: target velocities reach the motor.
  bool enabled() const { return st_.phase == LinkPhase::running && st_.state == cia402::State::operation_enabled; }
  const DriveLinkStatus& status() const { return st_; }

 private:
  // Sends the SDO write of the current configure phase and arms its time-out.
  void send_sdo(std::int64_t now_us, FrameBatch& out);

  DriveLinkSettings s_;
  DriveLinkStatus st_;
  std::int64_t last_heard_us_ = 0;   // last heartbeat (or SDO answer during configuration), µs
  std::int64_t sent_us_ = 0;         // last SDO write or NMT start sent, µs
  bool pending_send_ = true;         // the current phase's request is due now
  std::int64_t last_reset_us_ = 0;   // last fault reset pulse, µs
  bool seen_fault_state_ = false;    // the statusword reported fault since the EMCY
  bool started_ = false;             // start() ran once (later starts count as restarts)
};

}  // namespace robuter::hal::can

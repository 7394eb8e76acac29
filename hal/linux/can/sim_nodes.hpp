// SPDX-License-Identifier: GPL-3.0-or-later
// Simulated CAN nodes for tests: a CiA 402 velocity-mode drive and an ultrasonic node, each on a FrameTransport.
#pragma once

#include <array>
#include <cstdint>

#include "hal/linux/can/cia402.hpp"
#include "hal/linux/can/frame_transport.hpp"

namespace robuter::hal::can {

// A motor drive as the CiA 402 profile describes it, with the object dictionary subset robuterd
// uses (0x1016:01, 0x1017, 0x6007, 0x6040/41, 0x6060, 0x6064, 0x606C, 0x60FF) and fault, silence
// and reboot injection. The motor follows the target velocity within an acceleration limit.
// Heartbeat consumer (CiA 301): once 0x1016:01 names a node and a time and that node's first
// heartbeat came, a gap longer than the time is a heartbeat event: EMCY 0x8130 and the 0x6007
// reaction (1 fault, 2 disable voltage, 3 quick stop: velocity to 0 at the acceleration limit);
// the next heartbeat of that node sends the EMCY error reset.
class SimDriveNode {
 public:
  SimDriveNode(FrameTransport& bus, std::uint8_t node, double accel_counts_s2 = 1e9);
  // Takes every waiting frame and advances to `now_us` (call every tick).
  void step(std::int64_t now_us);

  // A fault with EMCY `code` (e.g. 0x2310 over-current): fault reaction, then fault. The cause
  // stays until clear_fault_cause(); a fault reset before that leaves the drive in fault.
  void inject_fault(std::uint16_t code);
  void clear_fault_cause() { fault_cause_ = false; }
  // Silent: sends nothing at all (a cut cable, a dead drive); frames are still taken.
  void set_silent(bool on) { silent_ = on; }
  // Power cycle: boot-up, pre-operational, every written object back to its default.
  void reboot(std::int64_t now_us);
  // Refuses SDO writes to 0x6060 (abort 0x06090030, value range exceeded).
  void refuse_mode(bool on) { refuse_mode_ = on; }
  // Sends no EMCY (a drive whose emergency object is not configured): faults show in the
  // statusword only.
  void set_emcy(bool on) { emcy_ = on; }

  cia402::State state() const { return state_; }
  cia402::NmtState nmt_state() const { return nmt_; }
  std::int8_t mode() const { return mode_; }
  std::uint16_t heartbeat_ms() const { return heartbeat_ms_; }
  std::int32_t target_velocity() const { return target_; }   // increments/s
  double velocity() const { return velocity_; }               // increments/s
  std::int32_t position() const { return static_cast<std::int32_t>(static_cast<std::int64_t>(position_)); }
  void set_position(double counts) { position_ = counts; }    // increments
  std::uint16_t last_controlword() const { return controlword_; }
  std::uint32_t rpdos() const { return rpdos_; }              // RPDO1 frames taken, count
  std::uint8_t consumer_node() const { return consumer_node_; }   // 0x1016:01 node id (0: none)
  std::uint16_t consumer_ms() const { return consumer_ms_; }      // 0x1016:01 time, ms
  std::int16_t abort_option() const { return abort_option_; }     // 0x6007
  std::uint32_t heartbeat_events() const { return heartbeat_events_; }  // consumer heartbeat losses, count
  std::int64_t last_consumed_us() const { return last_consumed_us_; }   // last heartbeat of the watched node, µs (-1 none)
  bool consumer_lost() const { return consumer_lost_; }           // the watched heartbeat is missing now

 private:
  void take(const can_frame& f, std::int64_t now_us);
  void send(const can_frame& f);
  // The 0x6007 reaction to a lost heartbeat of the watched node.
  void lose_connection();

  FrameTransport& bus_;
  std::uint8_t node_;
  double accel_;                                   // acceleration limit, increments/s²
  cia402::NmtState nmt_ = cia402::NmtState::boot_up;
  cia402::State state_ = cia402::State::not_ready_to_switch_on;
  std::int8_t mode_ = 0;                           // 0x6060 (0 = none until written)
  std::uint16_t heartbeat_ms_ = 0;                 // 0x1017 (0 = no heartbeat until written)
  std::uint16_t controlword_ = 0;                  // last 0x6040
  std::int32_t target_ = 0;                        // 0x60FF, increments/s
  double velocity_ = 0.0;                          // increments/s
  double position_ = 0.0;                          // increments
  std::int64_t last_us_ = -1;                      // time of the previous step, µs
  std::int64_t next_heartbeat_us_ = 0;             // µs
  bool booted_ = false;                            // boot-up message sent
  bool fault_cause_ = false;                       // the injected fault's cause is still present
  bool silent_ = false;
  bool refuse_mode_ = false;
  bool emcy_ = true;                               // EMCY frames are sent
  std::uint32_t rpdos_ = 0;
  std::uint8_t consumer_node_ = 0;                 // 0x1016:01 bits 16..23: the node watched (0: none)
  std::uint16_t consumer_ms_ = 0;                  // 0x1016:01 bits 0..15: its heartbeat time, ms (0: off)
  std::int16_t abort_option_ = 1;                  // 0x6007 (CiA 402 default 1: fault)
  std::int64_t last_consumed_us_ = -1;             // last heartbeat of the watched node, µs (-1: none yet)
  bool consumer_lost_ = false;                     // a heartbeat event happened and the node is still silent
  std::uint32_t heartbeat_events_ = 0;             // heartbeat events, count
};

// An ultrasonic node of four transducers (docs/CAN.md frame set): fire → ranges once every
// fired transducer heard its echo, or after the firing's time-out when one did not; heartbeat
// every 100 ms; status with the faulty-transducer mask.
class SimSonarNode {
 public:
  static constexpr std::int64_t kHeartbeatUs = 100'000;  // heartbeat period, µs

  SimSonarNode(FrameTransport& bus, std::uint8_t node);
  void step(std::int64_t now_us);
  // What transducer i would measure, mm (beyond the time-out's reach: no echo, reported 0).
  void set_range(int i, std::uint16_t mm) { world_[static_cast<std::size_t>(i)] = mm; }
  void set_faulty(std::uint8_t mask) { faulty_ = mask; }
  void set_silent(bool on) { silent_ = on; }
  std::uint32_t firings() const { return firings_; }
  cia402::NmtState nmt_state() const { return nmt_; }

 private:
  void send(const can_frame& f);

  FrameTransport& bus_;
  std::uint8_t node_;
  cia402::NmtState nmt_ = cia402::NmtState::pre_operational;
  std::array<std::uint16_t, 4> world_{};  // true ranges, mm
  std::uint8_t faulty_ = 0;               // faulty transducers, bit i
  bool silent_ = false;
  bool busy_ = false;                     // a firing waits for its echoes
  std::uint8_t mask_ = 0;                 // transducers of that firing
  std::uint32_t reach_mm_ = 0;            // farthest echo within the firing's time-out, mm
  std::int64_t answer_us_ = 0;            // when the ranges go out, µs
  std::int64_t next_heartbeat_us_ = 0;    // µs
  bool booted_ = false;                   // boot-up message sent
  std::uint32_t firings_ = 0;             // fire requests taken, count
};

}  // namespace robuter::hal::can

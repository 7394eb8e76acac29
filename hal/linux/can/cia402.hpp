// SPDX-License-Identifier: GPL-3.0-or-later
// CANopen (CiA 301) and CiA 402 subset for a velocity-mode drive: frames, statusword decoding, state machine. Pure.
#pragma once

#include <linux/can.h>

#include <cstdint>

#include "kernel/vocabulary.hpp"

namespace robuter::hal::can::cia402 {

// COB-IDs of the CiA 301 predefined connection set (function code; add the node id, 1..127).
inline constexpr canid_t kNmt = 0x000;         // NMT command, from the host (no node id)
inline constexpr canid_t kSync = 0x080;        // SYNC, from the host (no node id)
inline constexpr canid_t kEmcy = 0x080;        // + id: emergency object from a node
inline constexpr canid_t kTpdo1 = 0x180;       // + id: statusword, velocity actual value
inline constexpr canid_t kRpdo1 = 0x200;       // + id: controlword, target velocity
inline constexpr canid_t kTpdo2 = 0x280;       // + id: position actual value
inline constexpr canid_t kSdoResponse = 0x580; // + id: SDO server → host
inline constexpr canid_t kSdoRequest = 0x600;  // + id: host → SDO server
inline constexpr canid_t kHeartbeat = 0x700;   // + id: NMT state of a node

// Object dictionary entries used (index; sub-index 0 unless noted).
inline constexpr std::uint16_t kObjConsumerHeartbeat = 0x1016;  // sub 1: u32, node id << 16 | time in ms
inline constexpr std::uint16_t kObjHeartbeatProducer = 0x1017;  // u16, ms
inline constexpr std::uint16_t kObjAbortConnection = 0x6007;    // i16: reaction to a lost connection
inline constexpr std::int16_t kAbortQuickStop = 3;              // 0x6007 value: quick stop (1 fault, 2 disable voltage)
inline constexpr std::uint16_t kEmcyHeartbeatError = 0x8130;    // EMCY: life guard or heartbeat error
inline constexpr std::uint16_t kObjControlword = 0x6040;        // u16
inline constexpr std::uint16_t kObjStatusword = 0x6041;         // u16
inline constexpr std::uint16_t kObjModesOfOperation = 0x6060;   // i8
inline constexpr std::uint16_t kObjPositionActual = 0x6064;     // i32, increments
inline constexpr std::uint16_t kObjVelocityActual = 0x606C;     // i32, increments/s
inline constexpr std::uint16_t kObjTargetVelocity = 0x60FF;     // i32, increments/s
inline constexpr std::int8_t kModeProfileVelocity = 3;          // 0x6060 value: profile velocity mode

// NMT command specifiers (byte 0 of an NMT frame).
enum class NmtCommand : std::uint8_t {
  start = 0x01,            // → operational
  stop = 0x02,             // → stopped
  enter_pre_operational = 0x80,
  reset_node = 0x81,
  reset_communication = 0x82,
};

// NMT states as a heartbeat reports them (byte 0).
enum class NmtState : std::uint8_t {
  boot_up = 0x00,
  stopped = 0x04,
  operational = 0x05,
  pre_operational = 0x7F,
};

// Controlword commands (0x6040), bits 0..3 and 7 (CiA 402 table "device control commands").
inline constexpr std::uint16_t kCwShutdown = 0x0006;          // → ready to switch on
inline constexpr std::uint16_t kCwSwitchOn = 0x0007;          // → switched on (also "disable operation")
inline constexpr std::uint16_t kCwEnableOperation = 0x000F;   // → operation enabled
inline constexpr std::uint16_t kCwDisableVoltage = 0x0000;    // → switch on disabled
inline constexpr std::uint16_t kCwQuickStop = 0x0002;         // → quick stop active
inline constexpr std::uint16_t kCwFaultReset = 0x0080;        // rising edge of bit 7: fault → switch on disabled

// Statusword bits (0x6041).
inline constexpr std::uint16_t kSwReadyToSwitchOn = 1u << 0;
inline constexpr std::uint16_t kSwSwitchedOn = 1u << 1;
inline constexpr std::uint16_t kSwOperationEnabled = 1u << 2;
inline constexpr std::uint16_t kSwFault = 1u << 3;
inline constexpr std::uint16_t kSwVoltageEnabled = 1u << 4;
inline constexpr std::uint16_t kSwQuickStop = 1u << 5;            // 0 = quick stop active
inline constexpr std::uint16_t kSwSwitchOnDisabled = 1u << 6;
inline constexpr std::uint16_t kSwWarning = 1u << 7;
inline constexpr std::uint16_t kSwRemote = 1u << 9;
inline constexpr std::uint16_t kSwTargetReached = 1u << 10;

// The power drive system's states (CiA 402 finite state automaton), with their words for logs.
#define ROBUTER_CIA402_STATES(X)                                                                       \
  X(not_ready_to_switch_on, "not-ready-to-switch-on")                                                  \
  X(switch_on_disabled, "switch-on-disabled")                                                          \
  X(ready_to_switch_on, "ready-to-switch-on")                                                          \
  X(switched_on, "switched-on")                                                                        \
  X(operation_enabled, "operation-enabled")                                                            \
  X(quick_stop_active, "quick-stop-active")                                                            \
  X(fault_reaction_active, "fault-reaction-active")                                                    \
  X(fault, "fault")
enum class State : std::uint8_t { ROBUTER_CIA402_STATES(ROBUTER_VOCAB_ENUMERATOR) };
ROBUTER_VOCABULARY(State, ROBUTER_CIA402_STATES, "fault");
// The state a statusword reports (bits 0..3, 5, 6 per the CiA 402 table).
State decode_statusword(std::uint16_t sw);
// The statusword a drive in `s` reports: the state bits, plus voltage enabled from "ready to
// switch on" on and remote; `extra` adds other bits (warning, target reached…).
std::uint16_t encode_statusword(State s, std::uint16_t extra = 0);
// Host side: the controlword that moves a drive in `s` one transition toward operation enabled
// (`enable`) or toward switched on (servo off: power stage disabled, the drive keeps its
// parameters and re-enables in one step). In fault: `fault_reset` sends bit 7 (the caller
// makes the rising edge by alternating with 0).
std::uint16_t next_controlword(State s, bool enable, bool fault_reset);
// Drive side: the state after `cw` arrives in `s` (transitions 2..12 and 15; bit 7's rising
// edge needs the previous controlword). Not-ready and fault-reaction move on their own.
State apply_controlword(State s, std::uint16_t cw, std::uint16_t previous_cw);

// ---- frames (all multi-byte values little-endian, as CANopen transmits them) ----

can_frame nmt(NmtCommand cmd, std::uint8_t node);  // node 0 = every node
can_frame sync();
can_frame heartbeat(std::uint8_t node, NmtState s);
can_frame rpdo1(std::uint8_t node, std::uint16_t controlword, std::int32_t target_velocity);
can_frame tpdo1(std::uint8_t node, std::uint16_t statusword, std::int32_t velocity_actual);
can_frame tpdo2(std::uint8_t node, std::int32_t position_actual);
can_frame emcy(std::uint8_t node, std::uint16_t error_code, std::uint8_t error_register);
// Expedited SDO download (write) of a 1, 2 or 4-byte value.
can_frame sdo_download(std::uint8_t node, std::uint16_t index, std::uint8_t sub, std::uint32_t value,
                       std::uint8_t size);
can_frame sdo_download_ack(std::uint8_t node, std::uint16_t index, std::uint8_t sub);
can_frame sdo_abort(std::uint8_t node, std::uint16_t index, std::uint8_t sub, std::uint32_t code);

// The node id a frame of function code `base` comes from, or 0 when it is not such a frame
// (standard 11-bit id, no RTR or error flag, id in base+1..base+127).
std::uint8_t node_of(const can_frame& f, canid_t base);

// Parsed frames; each parser returns false on a wrong id, flags or length.
bool parse_rpdo1(const can_frame& f, std::uint16_t& controlword, std::int32_t& target_velocity);
bool parse_tpdo1(const can_frame& f, std::uint16_t& statusword, std::int32_t& velocity_actual);
bool parse_tpdo2(const can_frame& f, std::int32_t& position_actual);
bool parse_emcy(const can_frame& f, std::uint16_t& error_code, std::uint8_t& error_register);
bool parse_heartbeat(const can_frame& f, NmtState& s);
bool parse_nmt(const can_frame& f, NmtCommand& cmd, std::uint8_t& node);

// An SDO request or response, as far as this subset needs.
struct SdoMessage {
  std::uint8_t command = 0;   // command specifier byte (0x2F/0x2B/0x23 download, 0x60 ack, 0x80 abort)
  std::uint16_t index = 0;    // object index
  std::uint8_t sub = 0;       // sub-index
  std::uint32_t data = 0;     // value (download) or abort code
};
bool parse_sdo(const can_frame& f, canid_t base, SdoMessage& out);

}  // namespace robuter::hal::can::cia402

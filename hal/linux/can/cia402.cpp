// SPDX-License-Identifier: GPL-3.0-or-later
// CiA 301/402 subset: statusword decoding, the drive state machine on both sides, frame encoders and parsers.
#include "hal/linux/can/cia402.hpp"

#include "hal/linux/can/frame_bytes.hpp"

namespace robuter::hal::can::cia402 {

namespace {
using bytes::frame;
using bytes::get16;
using bytes::get32;
using bytes::put16;
using bytes::put32;
// Standard data frame with the exact id `id` and at least `len` bytes.
bool is(const can_frame& f, canid_t id, std::uint8_t len) {
  return (f.can_id & (CAN_EFF_FLAG | CAN_RTR_FLAG | CAN_ERR_FLAG)) == 0 && f.can_id == id && f.len >= len;
}
}  // namespace

// The CiA 402 table: xxxx xxxx x0xx 0000 not ready, x1xx 0000 switch on disabled, x01x 0001
// ready, x01x 0011 switched on, x01x 0111 enabled, x00x 0111 quick stop, x0xx 1111 fault
// reaction, x0xx 1000 fault. A pattern outside the table with the fault bit is a fault (the
// safe reading); any other is "not ready".
State decode_statusword(std::uint16_t sw) {
  const unsigned a = sw & 0x4Fu, b = sw & 0x6Fu;
  if (a == 0x00) return State::not_ready_to_switch_on;
  if (a == 0x40) return State::switch_on_disabled;
  if (b == 0x21) return State::ready_to_switch_on;
  if (b == 0x23) return State::switched_on;
  if (b == 0x27) return State::operation_enabled;
  if (b == 0x07) return State::quick_stop_active;
  if (a == 0x0F) return State::fault_reaction_active;
  if (a == 0x08) return State::fault;
  return (sw & kSwFault) ? State::fault : State::not_ready_to_switch_on;
}

std::uint16_t encode_statusword(State s, std::uint16_t extra) {
  std::uint16_t sw = 0;
  switch (s) {
    case State::not_ready_to_switch_on: sw = 0x0000; break;
    case State::switch_on_disabled: sw = 0x0040; break;
    case State::ready_to_switch_on: sw = 0x0021 | kSwVoltageEnabled; break;
    case State::switched_on: sw = 0x0023 | kSwVoltageEnabled; break;
    case State::operation_enabled: sw = 0x0027 | kSwVoltageEnabled; break;
    case State::quick_stop_active: sw = 0x0007 | kSwVoltageEnabled; break;
    case State::fault_reaction_active: sw = 0x000F | kSwVoltageEnabled; break;
    case State::fault: sw = 0x0008; break;
  }
  return static_cast<std::uint16_t>(sw | kSwRemote | extra);
}

// One transition per call, so the drive confirms each state in its statusword before the next.
std::uint16_t next_controlword(State s, bool enable, bool fault_reset) {
  switch (s) {
    case State::switch_on_disabled: return kCwShutdown;
    case State::ready_to_switch_on: return kCwSwitchOn;
    case State::switched_on: return enable ? kCwEnableOperation : kCwSwitchOn;
    case State::operation_enabled: return enable ? kCwEnableOperation : kCwSwitchOn;
    case State::quick_stop_active: return kCwDisableVoltage;
    case State::fault: return fault_reset ? kCwFaultReset : kCwDisableVoltage;
    case State::not_ready_to_switch_on:
    case State::fault_reaction_active: return kCwDisableVoltage;
  }
  return kCwDisableVoltage;
}

// Commands by the bit patterns of the CiA 402 "device control commands" table; transition
// numbers in the comments are the standard's.
State apply_controlword(State s, std::uint16_t cw, std::uint16_t previous_cw) {
  const bool shutdown = (cw & 0x87u) == 0x06u;
  const bool switch_on = (cw & 0x8Fu) == 0x07u;  // also "disable operation"
  const bool enable_op = (cw & 0x8Fu) == 0x0Fu;
  const bool disable_voltage = (cw & 0x82u) == 0x00u;
  const bool quick_stop = (cw & 0x86u) == 0x02u;
  const bool reset_edge = (cw & kCwFaultReset) && !(previous_cw & kCwFaultReset);
  switch (s) {
    case State::switch_on_disabled:
      if (shutdown) return State::ready_to_switch_on;  // 2
      break;
    case State::ready_to_switch_on:
      if (switch_on) return State::switched_on;             // 3
      if (enable_op) return State::operation_enabled;       // 3 + 4
      if (disable_voltage || quick_stop) return State::switch_on_disabled;  // 7
      break;
    case State::switched_on:
      if (enable_op) return State::operation_enabled;       // 4
      if (shutdown) return State::ready_to_switch_on;       // 6
      if (disable_voltage || quick_stop) return State::switch_on_disabled;  // 10
      break;
    case State::operation_enabled:
      if (switch_on) return State::switched_on;             // 5
      if (shutdown) return State::ready_to_switch_on;       // 8
      if (disable_voltage) return State::switch_on_disabled;  // 9
      if (quick_stop) return State::quick_stop_active;      // 11
      break;
    case State::quick_stop_active:
      if (disable_voltage) return State::switch_on_disabled;  // 12
      break;
    case State::fault:
      if (reset_edge) return State::switch_on_disabled;     // 15
      break;
    case State::not_ready_to_switch_on:
    case State::fault_reaction_active: break;  // leave on their own (1, 14)
  }
  return s;
}

can_frame nmt(NmtCommand cmd, std::uint8_t node) {
  can_frame f = frame(kNmt, 2);
  f.data[0] = static_cast<std::uint8_t>(cmd);
  f.data[1] = node;
  return f;
}

can_frame sync() { return frame(kSync, 0); }

can_frame heartbeat(std::uint8_t node, NmtState s) {
  can_frame f = frame(kHeartbeat + node, 1);
  f.data[0] = static_cast<std::uint8_t>(s);
  return f;
}

can_frame rpdo1(std::uint8_t node, std::uint16_t controlword, std::int32_t target_velocity) {
  can_frame f = frame(kRpdo1 + node, 6);
  put16(f.data, controlword);
  put32(f.data + 2, static_cast<std::uint32_t>(target_velocity));
  return f;
}

can_frame tpdo1(std::uint8_t node, std::uint16_t statusword, std::int32_t velocity_actual) {
  can_frame f = frame(kTpdo1 + node, 6);
  put16(f.data, statusword);
  put32(f.data + 2, static_cast<std::uint32_t>(velocity_actual));
  return f;
}

can_frame tpdo2(std::uint8_t node, std::int32_t position_actual) {
  can_frame f = frame(kTpdo2 + node, 4);
  put32(f.data, static_cast<std::uint32_t>(position_actual));
  return f;
}

can_frame emcy(std::uint8_t node, std::uint16_t error_code, std::uint8_t error_register) {
  can_frame f = frame(kEmcy + node, 8);
  put16(f.data, error_code);
  f.data[2] = error_register;
  return f;
}

// Command byte 0x23/0x2B/0x2F: expedited download with the size indicated (n = 4 − size unused bytes).
can_frame sdo_download(std::uint8_t node, std::uint16_t index, std::uint8_t sub, std::uint32_t value,
                       std::uint8_t size) {
  can_frame f = frame(kSdoRequest + node, 8);
  const unsigned unused = size >= 1 && size <= 4 ? 4u - size : 0u;
  f.data[0] = static_cast<std::uint8_t>(0x23u | (unused << 2));
  put16(f.data + 1, index);
  f.data[3] = sub;
  put32(f.data + 4, size >= 4 ? value : value & ((1u << (8 * size)) - 1u));
  return f;
}

can_frame sdo_download_ack(std::uint8_t node, std::uint16_t index, std::uint8_t sub) {
  can_frame f = frame(kSdoResponse + node, 8);
  f.data[0] = 0x60;
  put16(f.data + 1, index);
  f.data[3] = sub;
  return f;
}

can_frame sdo_abort(std::uint8_t node, std::uint16_t index, std::uint8_t sub, std::uint32_t code) {
  can_frame f = frame(kSdoResponse + node, 8);
  f.data[0] = 0x80;
  put16(f.data + 1, index);
  f.data[3] = sub;
  put32(f.data + 4, code);
  return f;
}

std::uint8_t node_of(const can_frame& f, canid_t base) {
  if (f.can_id & (CAN_EFF_FLAG | CAN_RTR_FLAG | CAN_ERR_FLAG)) return 0;
  if (f.can_id <= base || f.can_id > base + 127) return 0;
  return static_cast<std::uint8_t>(f.can_id - base);
}

bool parse_rpdo1(const can_frame& f, std::uint16_t& controlword, std::int32_t& target_velocity) {
  if (node_of(f, kRpdo1) == 0 || f.len < 6) return false;
  controlword = get16(f.data);
  target_velocity = static_cast<std::int32_t>(get32(f.data + 2));
  return true;
}

bool parse_tpdo1(const can_frame& f, std::uint16_t& statusword, std::int32_t& velocity_actual) {
  if (node_of(f, kTpdo1) == 0 || f.len < 6) return false;
  statusword = get16(f.data);
  velocity_actual = static_cast<std::int32_t>(get32(f.data + 2));
  return true;
}

bool parse_tpdo2(const can_frame& f, std::int32_t& position_actual) {
  if (node_of(f, kTpdo2) == 0 || f.len < 4) return false;
  position_actual = static_cast<std::int32_t>(get32(f.data));
  return true;
}

bool parse_emcy(const can_frame& f, std::uint16_t& error_code, std::uint8_t& error_register) {
  if (node_of(f, kEmcy) == 0 || f.len < 3) return false;
  error_code = get16(f.data);
  error_register = f.data[2];
  return true;
}

bool parse_heartbeat(const can_frame& f, NmtState& s) {
  if (node_of(f, kHeartbeat) == 0 || f.len < 1) return false;
  const std::uint8_t b = f.data[0] & 0x7F;  // bit 7 is the (node guarding) toggle bit
  if (b != 0x00 && b != 0x04 && b != 0x05 && b != 0x7F) return false;
  s = static_cast<NmtState>(b);
  return true;
}

bool parse_nmt(const can_frame& f, NmtCommand& cmd, std::uint8_t& node) {
  if (!is(f, kNmt, 2)) return false;
  const std::uint8_t c = f.data[0];
  if (c != 0x01 && c != 0x02 && c != 0x80 && c != 0x81 && c != 0x82) return false;
  cmd = static_cast<NmtCommand>(c);
  node = f.data[1];
  return true;
}

bool parse_sdo(const can_frame& f, canid_t base, SdoMessage& out) {
  if (node_of(f, base) == 0 || f.len < 8) return false;
  out.command = f.data[0];
  out.index = get16(f.data + 1);
  out.sub = f.data[3];
  out.data = get32(f.data + 4);
  return true;
}

}  // namespace robuter::hal::can::cia402

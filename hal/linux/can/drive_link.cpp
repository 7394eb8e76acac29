// SPDX-License-Identifier: GPL-3.0-or-later
// The host's CiA 402 drive bring-up and supervision: SDO configuration, NMT start, controlword stepping, faults.
#include "hal/linux/can/drive_link.hpp"

namespace robuter::hal::can {

using namespace cia402;

namespace {
constexpr std::int64_t kUsPerMs = 1000;
}  // namespace

// The liveness timer restarts too, so a drive gets a whole time-out to answer the first write.
void DriveLink::start(std::int64_t now_us) {
  if (started_) ++st_.restarts;
  started_ = true;
  const std::uint32_t restarts = st_.restarts;
  st_ = DriveLinkStatus{};
  st_.restarts = restarts;
  last_heard_us_ = now_us;
  pending_send_ = true;
  seen_fault_state_ = false;
  last_reset_us_ = now_us;
}

void DriveLink::send_sdo(std::int64_t now_us, FrameBatch& out) {
  switch (st_.phase) {
    case LinkPhase::configure_mode:
      out.push(sdo_download(s_.node, kObjModesOfOperation, 0, static_cast<std::uint8_t>(kModeProfileVelocity), 1));
      break;
    case LinkPhase::configure_heartbeat:
      out.push(sdo_download(s_.node, kObjHeartbeatProducer, 0, s_.heartbeat_ms, 2));
      break;
    case LinkPhase::configure_consumer:
      out.push(sdo_download(s_.node, kObjConsumerHeartbeat, 1,
                            static_cast<std::uint32_t>(s_.host_node) << 16 | s_.watchdog_ms, 4));
      break;
    default:
      out.push(sdo_download(s_.node, kObjAbortConnection, 0, static_cast<std::uint16_t>(kAbortQuickStop), 2));
      break;
  }
  sent_us_ = now_us;
  pending_send_ = false;
}

// Dispatch by function code. A boot-up heartbeat means the drive reset: everything written to it
// is gone, so the bring-up starts over.
bool DriveLink::on_frame(const can_frame& f, std::int64_t now_us) {
  NmtState nmt{};
  if (node_of(f, kHeartbeat) == s_.node && parse_heartbeat(f, nmt)) {
    last_heard_us_ = now_us;
    if (nmt == NmtState::boot_up) {
      if (st_.phase != LinkPhase::configure_mode || !pending_send_) start(now_us);
      return true;
    }
    if (st_.phase == LinkPhase::starting && nmt == NmtState::operational) st_.phase = LinkPhase::running;
    else if (st_.phase == LinkPhase::running && nmt != NmtState::operational) {
      st_.phase = LinkPhase::starting;  // someone stopped it: start it again
      pending_send_ = true;
    }
    return true;
  }
  SdoMessage sdo;
  if (node_of(f, kSdoResponse) == s_.node && parse_sdo(f, kSdoResponse, sdo)) {
    const bool mode = st_.phase == LinkPhase::configure_mode && sdo.index == kObjModesOfOperation;
    const bool hb = st_.phase == LinkPhase::configure_heartbeat && sdo.index == kObjHeartbeatProducer;
    const bool consumer = st_.phase == LinkPhase::configure_consumer && sdo.index == kObjConsumerHeartbeat;
    const bool abort = st_.phase == LinkPhase::configure_abort && sdo.index == kObjAbortConnection;
    if (!mode && !hb && !consumer && !abort) return true;  // a late answer to an earlier write
    last_heard_us_ = now_us;
    if (sdo.command == 0x60) {
      st_.sdo_abort = 0;
      // The drive-side watchdog (docs/SAFETY.md): after its own heartbeat, the drive learns to
      // watch the host's and to quick-stop when it stops (skipped when watchdog_ms is 0).
      if (mode) st_.phase = LinkPhase::configure_heartbeat;
      else if (hb) st_.phase = s_.watchdog_ms > 0 ? LinkPhase::configure_consumer : LinkPhase::starting;
      else if (consumer) st_.phase = LinkPhase::configure_abort;
      else st_.phase = LinkPhase::starting;
      pending_send_ = true;
    } else if (sdo.command == 0x80) {
      st_.sdo_abort = sdo.data == 0 ? 0xFFFFFFFFu : sdo.data;  // retried after fault_reset_ms
    }
    return true;
  }
  std::uint16_t sw = 0;
  std::int32_t v = 0;
  if (node_of(f, kTpdo1) == s_.node && parse_tpdo1(f, sw, v)) {
    st_.statusword = sw;
    st_.state = decode_statusword(sw);
    st_.velocity = v;
    const bool in_fault = st_.state == State::fault || st_.state == State::fault_reaction_active;
    if (in_fault) seen_fault_state_ = true;
    else if (seen_fault_state_) {  // left the fault state: the error was reset
      seen_fault_state_ = false;
      st_.emcy_active = false;
    }
    return true;
  }
  std::int32_t pos = 0;
  if (node_of(f, kTpdo2) == s_.node && parse_tpdo2(f, pos)) {
    st_.position = pos;
    st_.position_valid = true;
    ++st_.positions;
    return true;
  }
  std::uint16_t code = 0;
  std::uint8_t reg = 0;
  if (node_of(f, kEmcy) == s_.node && parse_emcy(f, code, reg)) {
    st_.emcy_code = code;
    st_.emcy_active = code != 0;
    return true;
  }
  return false;
}

// Bring-up requests are re-sent on their time-out (an SDO abort waits fault_reset_ms); once
// running, one RPDO1 per poll.
void DriveLink::poll(std::int64_t now_us, bool enable, std::int32_t target_velocity, FrameBatch& out) {
  switch (st_.phase) {
    case LinkPhase::configure_mode:
    case LinkPhase::configure_heartbeat:
    case LinkPhase::configure_consumer:
    case LinkPhase::configure_abort: {
      const std::int64_t wait = (st_.sdo_abort ? s_.fault_reset_ms : s_.sdo_timeout_ms) * kUsPerMs;
      if (pending_send_ || now_us - sent_us_ >= wait) send_sdo(now_us, out);
      return;
    }
    case LinkPhase::starting:
      if (pending_send_ || now_us - sent_us_ >= static_cast<std::int64_t>(s_.heartbeat_ms) * kUsPerMs) {
        out.push(nmt(NmtCommand::start, s_.node));
        sent_us_ = now_us;
        pending_send_ = false;
      }
      return;
    case LinkPhase::running: break;
  }
  bool reset = false;
  if (st_.state == State::fault) {
    // A pulse: 0x80 once per period, 0x00 otherwise, so every pulse is a rising edge.
    if (now_us - last_reset_us_ >= static_cast<std::int64_t>(s_.fault_reset_ms) * kUsPerMs) {
      reset = true;
      last_reset_us_ = now_us;
    }
  }
  const bool want = enable && !st_.emcy_active;
  st_.controlword = next_controlword(st_.state, want, reset);
  const bool on = want && st_.state == State::operation_enabled;
  out.push(rpdo1(s_.node, st_.controlword, on ? target_velocity : 0));
}

DriveFault DriveLink::fault(std::int64_t now_us) const {
  if (now_us - last_heard_us_ > static_cast<std::int64_t>(s_.heartbeat_timeout_ms) * kUsPerMs)
    return DriveFault::heartbeat_lost;
  if (st_.sdo_abort != 0 || st_.emcy_active) return DriveFault::fault;
  if (st_.phase != LinkPhase::running) return DriveFault::not_operational;
  if (st_.state == State::fault || st_.state == State::fault_reaction_active) return DriveFault::fault;
  return DriveFault::none;
}

}  // namespace robuter::hal::can

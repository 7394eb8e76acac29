// SPDX-License-Identifier: GPL-3.0-or-later
// The simulated drive and sonar nodes: CiA 301 NMT/SDO/heartbeat, CiA 402 state machine and PDOs, sonar frames.
#include "hal/linux/can/sim_nodes.hpp"

#include <algorithm>
#include <cmath>

#include "hal/linux/can/sonar_frames.hpp"

namespace robuter::hal::can {

using namespace cia402;

SimDriveNode::SimDriveNode(FrameTransport& bus, std::uint8_t node, double accel_counts_s2)
    : bus_(bus), node_(node), accel_(accel_counts_s2) {}

void SimDriveNode::send(const can_frame& f) {
  if (!silent_) bus_.send(f);
}

void SimDriveNode::reboot(std::int64_t now_us) {
  nmt_ = NmtState::boot_up;
  state_ = State::not_ready_to_switch_on;
  mode_ = 0;
  heartbeat_ms_ = 0;
  controlword_ = 0;
  target_ = 0;
  velocity_ = 0.0;
  booted_ = false;
  fault_cause_ = false;
  next_heartbeat_us_ = now_us;
  consumer_node_ = 0;
  consumer_ms_ = 0;
  abort_option_ = 1;
  last_consumed_us_ = -1;
  consumer_lost_ = false;
}

void SimDriveNode::lose_connection() {
  ++heartbeat_events_;
  consumer_lost_ = true;
  if (emcy_) send(emcy(node_, kEmcyHeartbeatError, 0x11));  // error register: generic + communication
  switch (abort_option_) {
    case 1: fault_cause_ = false; state_ = State::fault_reaction_active; break;
    case 2: if (state_ != State::fault) state_ = State::switch_on_disabled; break;
    case 3:
      if (state_ == State::operation_enabled) state_ = State::quick_stop_active;
      else if (state_ == State::ready_to_switch_on || state_ == State::switched_on) state_ = State::switch_on_disabled;
      break;
    default: break;  // 0: no action
  }
}

void SimDriveNode::inject_fault(std::uint16_t code) {
  fault_cause_ = true;
  state_ = State::fault_reaction_active;
  if (emcy_) send(emcy(node_, code, 0x01));  // error register bit 0: generic error
}

// NMT for this node or all; SDO writes to the two objects the host configures; RPDO1 and SYNC
// only while operational (CiA 301: PDOs run in "operational" only).
void SimDriveNode::take(const can_frame& f, std::int64_t now_us) {
  NmtState watched{};
  if (consumer_node_ != 0 && node_of(f, kHeartbeat) == consumer_node_ && parse_heartbeat(f, watched)) {
    last_consumed_us_ = now_us;
    if (consumer_lost_) {
      consumer_lost_ = false;
      if (emcy_) send(emcy(node_, 0x0000, 0x00));  // error reset: the connection is back
    }
    return;
  }
  NmtCommand cmd{};
  std::uint8_t target_node = 0;
  if (parse_nmt(f, cmd, target_node)) {
    if (target_node != 0 && target_node != node_) return;
    switch (cmd) {
      case NmtCommand::start: nmt_ = NmtState::operational; break;
      case NmtCommand::stop: nmt_ = NmtState::stopped; break;
      case NmtCommand::enter_pre_operational: nmt_ = NmtState::pre_operational; break;
      case NmtCommand::reset_node:
      case NmtCommand::reset_communication: reboot(now_us); break;
    }
    return;
  }
  SdoMessage sdo;
  if (node_of(f, kSdoRequest) == node_ && parse_sdo(f, kSdoRequest, sdo)) {
    if (nmt_ == NmtState::stopped) return;
    if ((sdo.command & 0xE3u) != 0x23u) return send(sdo_abort(node_, sdo.index, sdo.sub, 0x05040001));  // bad command
    if (sdo.index == kObjModesOfOperation && sdo.sub == 0) {
      if (refuse_mode_) return send(sdo_abort(node_, sdo.index, sdo.sub, 0x06090030));
      mode_ = static_cast<std::int8_t>(sdo.data & 0xFF);
    } else if (sdo.index == kObjConsumerHeartbeat && sdo.sub == 1) {
      consumer_node_ = static_cast<std::uint8_t>((sdo.data >> 16) & 0x7F);
      consumer_ms_ = static_cast<std::uint16_t>(sdo.data & 0xFFFF);
      last_consumed_us_ = -1;  // watching starts with that node's next heartbeat
      if (consumer_lost_ && emcy_) send(emcy(node_, 0x0000, 0x00));  // the old event is over
      consumer_lost_ = false;
    } else if (sdo.index == kObjAbortConnection && sdo.sub == 0) {
      abort_option_ = static_cast<std::int16_t>(sdo.data & 0xFFFF);
    } else if (sdo.index == kObjHeartbeatProducer && sdo.sub == 0) {
      heartbeat_ms_ = static_cast<std::uint16_t>(sdo.data & 0xFFFF);
      next_heartbeat_us_ = now_us;
    } else {
      return send(sdo_abort(node_, sdo.index, sdo.sub, 0x06020000));  // object does not exist
    }
    return send(sdo_download_ack(node_, sdo.index, sdo.sub));
  }
  if (nmt_ != NmtState::operational) return;
  std::uint16_t cw = 0;
  std::int32_t v = 0;
  if (node_of(f, kRpdo1) == node_ && parse_rpdo1(f, cw, v)) {
    ++rpdos_;
    const State before = state_;
    state_ = apply_controlword(state_, cw, controlword_);
    if (before == State::fault && state_ != State::fault) {
      if (fault_cause_) state_ = State::fault;  // the cause is still there: the reset fails
      else if (emcy_) send(emcy(node_, 0x0000, 0x00));  // error reset
    }
    controlword_ = cw;
    target_ = v;
    return;
  }
  if ((f.can_id & (CAN_EFF_FLAG | CAN_RTR_FLAG | CAN_ERR_FLAG)) == 0 && f.can_id == kSync) {
    send(tpdo1(node_, encode_statusword(state_), static_cast<std::int32_t>(std::lround(velocity_))));
    send(tpdo2(node_, position()));
  }
}

// Frames first (they act at this instant), then the motor and the heartbeat.
void SimDriveNode::step(std::int64_t now_us) {
  if (!booted_) {
    booted_ = true;
    send(heartbeat(node_, NmtState::boot_up));
    nmt_ = NmtState::pre_operational;
    if (state_ == State::not_ready_to_switch_on) state_ = State::switch_on_disabled;  // transition 1
  }
  can_frame f;
  while (bus_.receive(f)) take(f, now_us);
  if (consumer_ms_ > 0 && last_consumed_us_ >= 0 && !consumer_lost_ &&
      now_us - last_consumed_us_ > static_cast<std::int64_t>(consumer_ms_) * 1000)
    lose_connection();
  if (state_ == State::fault_reaction_active) state_ = State::fault;  // transition 14: motor stopped
  const double dt = last_us_ < 0 ? 0.0 : static_cast<double>(now_us - last_us_) * 1e-6;
  last_us_ = now_us;
  const bool driven = state_ == State::operation_enabled && mode_ == kModeProfileVelocity;
  const double want = driven ? static_cast<double>(target_) : 0.0;
  const double dv = std::clamp(want - velocity_, -accel_ * dt, accel_ * dt);
  velocity_ = state_ == State::fault || state_ == State::fault_reaction_active ? 0.0 : velocity_ + dv;
  position_ += velocity_ * dt;
  if (heartbeat_ms_ > 0 && now_us >= next_heartbeat_us_) {
    send(heartbeat(node_, nmt_));
    next_heartbeat_us_ = now_us + static_cast<std::int64_t>(heartbeat_ms_) * 1000;
  }
}

SimSonarNode::SimSonarNode(FrameTransport& bus, std::uint8_t node) : bus_(bus), node_(node) {}

void SimSonarNode::send(const can_frame& f) {
  if (!silent_) bus_.send(f);
}

// Fires only when operational and idle; the ranges go out once the last fired transducer heard
// its echo (2 · range / c), or one echo time-out later when one hears nothing within it (out of
// reach or faulty); the status just before them so the host knows which transducers failed.
void SimSonarNode::step(std::int64_t now_us) {
  if (!booted_) {
    booted_ = true;
    send(heartbeat(node_, NmtState::boot_up));
    next_heartbeat_us_ = now_us;
  }
  can_frame f;
  while (bus_.receive(f)) {
    NmtCommand cmd{};
    std::uint8_t target = 0;
    sonar::FireRequest req;
    if (parse_nmt(f, cmd, target)) {
      if (target != 0 && target != node_) continue;
      if (cmd == NmtCommand::start) nmt_ = NmtState::operational;
      else if (cmd == NmtCommand::stop) nmt_ = NmtState::stopped;
      else nmt_ = NmtState::pre_operational;
    } else if (node_of(f, sonar::kFire) == node_ && sonar::parse_fire(f, req)) {
      if (nmt_ != NmtState::operational || busy_) continue;
      ++firings_;
      busy_ = true;
      mask_ = req.mask;
      reach_mm_ = static_cast<std::uint32_t>(req.timeout_ms) * req.sound_speed_m_s / 2;
      std::int64_t listen_us = 0;
      for (std::size_t i = 0; i < 4; ++i) {
        if (!((mask_ >> i) & 1u)) continue;
        const bool heard = !((faulty_ >> i) & 1u) && world_[i] > 0 && world_[i] <= reach_mm_;
        const std::int64_t echo_us = req.sound_speed_m_s > 0 ? 2000LL * world_[i] / req.sound_speed_m_s : 0;
        listen_us = std::max(listen_us, heard ? echo_us : static_cast<std::int64_t>(req.timeout_ms) * 1000);
      }
      answer_us_ = now_us + listen_us;
    }
  }
  if (busy_ && now_us >= answer_us_) {
    busy_ = false;
    std::array<std::uint16_t, 4> mm{};
    for (std::size_t i = 0; i < 4; ++i) {
      const bool fired = (mask_ >> i) & 1u;
      const bool ok = !((faulty_ >> i) & 1u);
      mm[i] = fired && ok && world_[i] <= reach_mm_ ? world_[i] : 0;
    }
    send(sonar::status(node_, faulty_, 0));
    send(sonar::ranges(node_, mm));
  }
  if (now_us >= next_heartbeat_us_) {
    send(heartbeat(node_, nmt_));
    send(sonar::status(node_, faulty_, busy_ ? sonar::kStatusBusy : 0));
    next_heartbeat_us_ = now_us + kHeartbeatUs;
  }
}

}  // namespace robuter::hal::can

// Emergency process glue: reads the topics, runs the gate, publishes verdict, command and table.
#include "modules/emergency/emergency.hpp"

#include "hal/api/drive.hpp"
#include "kernel/kernel.hpp"
#include "kernel/log.hpp"

namespace robuter {

namespace {
// The configuration's units turned into the gate's (ticks of `tick_ns`).
safety::GateSettings gate_settings(const EmergencyConfig& cfg, const RobotConfig& robot, const EmergencyTuning& t,
                                   Nanos tick_ns) {
  safety::GateSettings s;
  s.enabled = static_cast<std::uint8_t>(cfg.mask & 7u);
  s.comm_limit_ticks = cfg.comm_limit_ticks;
  s.min_safety_mm = cfg.min_safety_mm;
  s.safety_mm_per_cm_s = cfg.safety_mm_per_cm_s;
  const Nanos ms = static_cast<Nanos>(cfg.motion_timeout_ms) * kNanosPerMilli;
  s.motion_timeout_ticks = tick_ns > 0 ? static_cast<std::uint32_t>((ms + tick_ns - 1) / tick_ns) : 0;
  s.latch = cfg.latch;
  s.wheel_base_mm = robot.wheel_base_mm;
  s.stale_ticks = t.stale_ticks;
  s.hold_limit_ticks = t.hold_limit_ticks;
  s.envelope = cfg.rule != "seed";
  const Nanos clear = static_cast<Nanos>(cfg.protective_clear_ms) * kNanosPerMilli;
  s.protective_clear_ticks = tick_ns > 0 ? static_cast<std::uint32_t>((clear + tick_ns - 1) / tick_ns) : 0;
  return s;
}

const char* cause_name(EmergencyCause c) {
  switch (c) {
    case EmergencyCause::none: return "none";
    case EmergencyCause::bumper: return "bumper";
    case EmergencyCause::obstacle: return "obstacle";
    case EmergencyCause::comm_loss: return "comm-loss";
    case EmergencyCause::stop_byte: return "stop-byte";
    case EmergencyCause::motion_timeout: return "motion-timeout";
    case EmergencyCause::drive_fault: return "drive-fault";
    case EmergencyCause::other: return "other";
    case EmergencyCause::heartbeat_lost: return "heartbeat-lost";
    case EmergencyCause::bus_passive: return "bus-error-passive";
    case EmergencyCause::bus_off: return "bus-off";
  }
  return "?";
}
// The executor's Posture.drive_health (a hal::DriveHealth) as the cause the gate reports.
EmergencyCause drive_cause(std::uint8_t health) {
  switch (static_cast<hal::DriveHealth>(health)) {
    case hal::DriveHealth::ok: return EmergencyCause::none;
    case hal::DriveHealth::silent: return EmergencyCause::heartbeat_lost;
    case hal::DriveHealth::bus_passive: return EmergencyCause::bus_passive;
    case hal::DriveHealth::bus_off: return EmergencyCause::bus_off;
    case hal::DriveHealth::fault: break;
  }
  return EmergencyCause::drive_fault;
}
}  // namespace

EmergencyModule::EmergencyModule(Blackboard& bb, hal::Bumpers& bumpers, const EmergencyConfig& cfg,
                                 const RobotConfig& robot, const EmergencyTuning& tuning)
    : bumpers_(bumpers),
      cfg_(cfg),
      robot_(robot),
      tuning_(tuning),
      gate_(gate_settings(cfg, robot, tuning, 10 * kNanosPerMilli)),
      envelope_(cfg, robot, 0.01),
      link_(bb.link_status.reader()),
      servo_(bb.servo_request.reader()),
      settings_(bb.us_settings.reader()),
      ranges_(bb.ranges.reader()),
      posture_(bb.posture.reader()),
      state_out_(bb.emergency.writer()),
      command_out_(bb.motion_command.writer()),
      selection_out_(bb.sonar_selection.writer()) {
  add_motion_source(MotionSource::link, bb.link_motion.reader());
  add_motion_source(MotionSource::go_to, bb.go_to_motion.reader());
  // Nothing is granted until the first activation: the executor reads "stop" meanwhile.
  EmergencyState s;
  s.enabled = gate_.enabled();
  state_out_.publish(s);
}

// Registration happens at start-up, before the periodic path.
bool EmergencyModule::add_motion_source(MotionSource source, Reader<MotionRequest> reader) {
  if (source_count_ == sources_.size()) return false;
  sources_[source_count_++] = Source{source, reader, reader.peek().seq};
  return true;
}

// The motion timeout is in ms: convert with the kernel's real tick; requests and link events
// from before the start do not count.
bool EmergencyModule::init(Kernel& k) {
  const std::uint8_t enabled = gate_.enabled();  // set_enabled() may have run before the start
  gate_ = safety::MotionGate(gate_settings(cfg_, robot_, tuning_, k.tick_ns()));
  gate_.set_enabled(enabled);
  envelope_.set_tick(static_cast<double>(k.tick_ns()) / 1e9);
  for (std::size_t i = 0; i < source_count_; ++i) sources_[i].seen_seq = sources_[i].reader.peek().seq;
  seen_stop_ = link_.peek().stop_seq;
  seen_reenable_ = link_.peek().reenable_seq;
  seen_servo_ = servo_.peek().seq;
  return true;
}

// Newest wins: among the sources whose seq changed since last seen, the latest request tick;
// ties go to the first registered (the operator's link).
void EmergencyModule::take_requests(safety::GateInputs& in) {
  const Source* best = nullptr;
  const MotionRequest* best_req = nullptr;
  for (std::size_t i = 0; i < source_count_; ++i) {
    Source& s = sources_[i];
    const MotionRequest& r = s.reader.peek();
    if (r.seq == s.seen_seq) continue;
    s.seen_seq = r.seq;
    if (best_req == nullptr || r.tick > best_req->tick) {
      best = &s;
      best_req = &r;
    }
  }
  if (best_req == nullptr) return;
  in.new_request = true;
  in.left = best_req->left;
  in.right = best_req->right;
  in.source = best->source;
  in.automatic = best->source != MotionSource::link && best->source != MotionSource::go_to;
}

// One activation: gather, decide, publish; the executor is triggered on a new command so a
// stop reaches the drive in the tick its cause was seen.
void EmergencyModule::run(Kernel& k) {
  const LinkStatus& link = link_.peek();
  const UltrasonicSettings& us = settings_.peek();
  const Posture& posture = posture_.peek();
  safety::GateInputs in;
  in.tick = k.tick();
  take_requests(in);
  in.servo_request = servo_.peek().seq != seen_servo_;
  seen_servo_ = servo_.peek().seq;
  in.stop_byte = link.stop_seq != seen_stop_;
  seen_stop_ = link.stop_seq;
  in.reenable = link.reenable_seq != seen_reenable_;
  seen_reenable_ = link.reenable_seq;
  in.bumpers = bumpers_.pressed();
  in.last_message_tick = link.last_message_tick;
  in.drive_fault = posture.drive_health != 0;
  in.drive_cause = drive_cause(posture.drive_health);
  in.servo_on = posture.servo;
  in.at_rest = at_rest(posture);
  in.ranges = &ranges_.peek();
  if (gate_.settings().envelope) {
    envelope_.observe(in.tick, posture, *in.ranges);
    in.envelope = &envelope_;
  }
  if (settings_.generation() > 0) {
    in.user_table = us.user_table;
    in.auto_toggle = us.auto_toggle;
  } else {
    in.auto_toggle = cfg_.auto_toggle;
  }

  const safety::GateDecision d = gate_.step(in);
  state_out_.publish(d.state);
  const MotionCommand& cur = command_out_.current();
  if (cur.seq == 0 || cur.left != d.left || cur.right != d.right || cur.stop != d.stop || cur.source != d.source) {
    const std::uint32_t seq = cur.seq + 1;
    command_out_.publish(MotionCommand{d.left, d.right, d.stop, seq, d.source});
    if (executor_) k.trigger(executor_);
  }
  if (selection_out_.current().active != d.selection) selection_out_.publish(SonarSelection{d.selection});
  log_transitions(d);
  last_ = d.state;
}

// Postures of one tick (the executor may run more than once in it) are one sample; a robot
// creeping by less than 0.1 mm and 0.01° between two samples counts as at rest.
bool EmergencyModule::at_rest(const Posture& p) {
  if (!have_pose_ || p.tick != pose_.tick) {
    moved_ = have_pose_ && (p.x != pose_.x || p.y != pose_.y || p.theta != pose_.theta);
    pose_ = p;
    have_pose_ = true;
  }
  return !moved_;
}

// Transitions only: a trip, a latch cleared or refused, a hold beginning or expiring.
void EmergencyModule::log_transitions(const safety::GateDecision& d) {
  const EmergencyState& s = d.state;
  if (d.tripped)
    log::warn("emergency: {} (sensor {}, safety {} mm){}", cause_name(s.cause), s.sensor, s.safety_mm,
              s.latched ? ", latched until XR" : "");
  else if (s.cause != last_.cause && s.cause != EmergencyCause::none)
    log::info("emergency: {} at rest", cause_name(s.cause));
  if (d.cleared) log::info("emergency: re-enabled");
  if (s.held && !last_.held) log::info("emergency: motion held for data of sensor {}", s.sensor);
  if (d.hold_expired) log::warn("emergency: held motion forgotten (no sensor data)");
  if (d.protective_started) log::info("emergency: protective stop (obstacle in the envelope)");
  if (d.resumed) log::info("emergency: automatic motion resumed, envelope clear");
}

}  // namespace robuter

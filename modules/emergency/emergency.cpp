// SPDX-License-Identifier: GPL-3.0-or-later
// Emergency process glue: reads the topics, runs the gate, publishes verdict, command and table.
#include "modules/emergency/emergency.hpp"

#include <algorithm>

#include "hal/api/drive.hpp"
#include "kernel/kernel.hpp"
#include "kernel/log.hpp"
#include "modules/emergency/obstacle_check.hpp"

namespace robuter {

namespace {
// The configuration's units turned into the gate's (ticks of `tick_ns`).
emergency::MotionGateSettings gate_settings(const EmergencyConfig& cfg, const RobotConfig& robot, const EmergencyTuning& t,
                                   Nanos tick_ns) {
  emergency::MotionGateSettings s;
  s.enabled = static_cast<std::uint8_t>(cfg.mask & kDetectAll);
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

// The executor's Posture.drive_health as the cause the gate reports.
EmergencyCause drive_cause(hal::DriveHealth health) {
  switch (health) {
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
      actions_(bb.operator_events.reader()),
      doors_wish_(bb.doors_detections.reader()),
      doors_status_(bb.doors_status.reader()),
      gate_status_(bb.gate_status.reader()),
      planner_status_(bb.planner_status.reader()),
      state_out_(bb.emergency.writer()),
      authority_out_(bb.authority.writer()),
      command_out_(bb.motion_command.writer()),
      selection_out_(bb.sonar_selection.writer()) {
  add_motion_source(MotionSource::link, bb.link_motion.reader());
  add_motion_source(MotionSource::go_to, bb.go_to_motion.reader());
  base_mask_ = gate_.enabled();
  // Nothing is granted until the first activation: the executor reads "stop" meanwhile.
  EmergencyState s;
  s.enabled = gate_.enabled();
  state_out_.publish(s);
  authority_out_.publish(arbiter_.authority());
}

// Registration happens at start-up, before the periodic path.
bool EmergencyModule::add_motion_source(MotionSource source, Reader<MotionRequest> reader) {
  if (source_count_ == sources_.size()) return false;
  sources_[source_count_++] = Source{source, reader};
  return true;
}

// The motion timeout is in ms: convert with the kernel's real tick; requests and link events
// from before the start do not count.
bool EmergencyModule::init(Kernel& k) {
  gate_ = emergency::MotionGate(gate_settings(cfg_, robot_, tuning_, k.tick_ns()));
  gate_.set_enabled(base_mask_);  // set_enabled() may have run before the start
  envelope_.set_tick(static_cast<double>(k.tick_ns()) / 1e9);
  for (std::size_t i = 0; i < source_count_; ++i) sources_[i].reader.copy();
  seen_stop_ = link_.peek().stop_seq;
  seen_reenable_ = link_.peek().reenable_seq;
  servo_.copy();
  seen_actions_ = actions_.peek().count;
  door_wish_seen_ = planner_status_.peek().door_wish;
  if (demo_at_boot_) arbiter_.start_at_boot(MotionSource::demo);
  MotionAuthority a = arbiter_.authority();
  a.detections = base_mask_;
  a.tick = k.tick();
  authority_out_.publish(a);
  return true;
}

// In the order the links took them; a gap (more than the ring holds) counts as an operator's
// motion, the case that takes the robot back from any mode.
void EmergencyModule::take_actions() {
  const OperatorEvents& ev = actions_.peek();
  if (ev.count - seen_actions_ > OperatorEvents::kCapacity) {
    arbiter_.lost_actions();
    seen_actions_ = ev.count - OperatorEvents::kCapacity;
  }
  for (; seen_actions_ != ev.count; ++seen_actions_)
    arbiter_.take(ev.ring[seen_actions_ % OperatorEvents::kCapacity].action);
}

// The seed's doors = ON after the finder: a hand-over lowers the detections without a second
// operator command, so it is off unless configured (docs/SAFETY.md §1).
void EmergencyModule::hand_over() {
  const ModeState gs = gate_status_.peek().state;
  if (hand_over_ && gs == ModeState::aligned && gate_seen_ != ModeState::aligned) arbiter_.hand_over_to_doors();
  gate_seen_ = gs;
  if (!door_loans_) return;
  // The planner at a narrow door of an XQ route lends the robot to the crossing; the crossing's
  // run ending by itself (crossed, or failed: the planner reads which) gives it back.
  const ModeStatus& d = doors_status_.peek();
  const std::uint32_t wish = planner_status_.peek().door_wish;
  if (wish != door_wish_seen_) {
    door_wish_seen_ = wish;
    arbiter_.lend_to_doors();  // only from the planner's run: anything else ignores it
    loan_doors_runs_ = d.runs;  // the crossing's runs before the loan's own starts
  }
  // The loan's crossing is the first run the crossing starts after it (no other can start while
  // it has the robot); its end gives the robot back.
  const bool ended = d.state == ModeState::crossed || d.state == ModeState::failed;
  if (arbiter_.authority().lent_by != MotionSource::link && ended && d.runs != loan_doors_runs_)
    arbiter_.give_back();
}

std::uint8_t EmergencyModule::detections() const {
  const ModeState d = doors_status_.peek().state;
  const bool in_door = d == ModeState::crossing || d == ModeState::waiting || d == ModeState::leaving;
  const DetectionRequest& wish = doors_wish_.peek();
  if (arbiter_.authority().owner == MotionSource::doors && in_door && wish.lower)
    return static_cast<std::uint8_t>(base_mask_ & wish.keep);
  return base_mask_;
}

// Only the owner's request counts; the others' are seen and dropped (a mode the operator ended
// may still be sending).
void EmergencyModule::take_requests(emergency::GateInputs& in) {
  for (std::size_t i = 0; i < source_count_; ++i) {
    Source& s = sources_[i];
    if (!s.reader.updated()) continue;
    const MotionRequest r = s.reader.copy();
    if (!arbiter_.accepts(s.source)) continue;
    in.new_request = true;
    in.left = r.left;
    in.right = r.right;
    in.source = s.source;
    in.automatic = emergency::automatic(s.source);
  }
}

// One activation: gather, decide, publish; the executor is triggered on a new command so a
// stop reaches the drive in the tick its cause was seen.
void EmergencyModule::run(Kernel& k) {
  const LinkStatus& link = link_.peek();
  const UltrasonicSettings& us = settings_.peek();
  const Posture& posture = posture_.peek();
  emergency::GateInputs in;
  in.tick = k.tick();
  const MotionAuthority before = arbiter_.authority();
  take_actions();
  hand_over();
  gate_.set_enabled(detections());
  take_requests(in);
  // The robot changed hands without a request of the new owner's (AT, Af, XH, XT0, a hand-over,
  // an AW before its first step): the last owner's speeds must not run on — a zero request.
  const MotionAuthority& now = arbiter_.authority();
  if (!in.new_request && (now.owner != before.owner || now.runs != before.runs)) {
    in.new_request = true;
    in.left = in.right = 0;
    in.source = now.owner;
  }
  in.servo_request = servo_.updated();
  if (in.servo_request) servo_.copy();
  in.stop_byte = link.stop_seq != seen_stop_;
  seen_stop_ = link.stop_seq;
  in.reenable = link.reenable_seq != seen_reenable_;
  seen_reenable_ = link.reenable_seq;
  in.bumpers = bumpers_.pressed();
  in.last_message_tick = link.last_message_tick;
  in.drive_fault = posture.drive_health != hal::DriveHealth::ok;
  in.drive_cause = drive_cause(posture.drive_health);
  in.servo_on = posture.servo;
  in.at_rest = at_rest(posture);
  in.ranges = &ranges_.peek();
  if (gate_.settings().envelope) {
    envelope_.observe(in.tick, posture, *in.ranges, in.at_rest);
    in.envelope = &envelope_;
  }
  if (settings_.advertised()) {
    in.user_table = us.user_table;
    in.auto_toggle = us.auto_toggle;
  } else {
    in.auto_toggle = cfg_.auto_toggle;
  }

  const emergency::GateDecision d = gate_.step(in);
  if (d.tripped) arbiter_.emergency_stop();
  else if (d.protective_started) arbiter_.protective_stop();
  state_out_.publish(d.state);
  MotionAuthority a = arbiter_.authority();
  a.detections = gate_.enabled();
  a.tick = in.tick;
  const MotionAuthority& was = authority_out_.current();
  if (a.owner != was.owner || a.runs != was.runs || a.ended != was.ended || a.detections != was.detections)
    authority_out_.publish(a);
  const MotionCommand& cur = command_out_.current();
  if (command_out_.generation() == 0 || cur.left != d.left || cur.right != d.right || cur.stop != d.stop || cur.source != d.source) {
    command_out_.publish(MotionCommand{d.left, d.right, d.stop, d.source});
    if (executor_) k.trigger(executor_);
  }
  // The ring fires the watch-dog set first and most often, listening 200 mm past the largest
  // safety distance (a reading never looks clear for lack of range): docs/SAFETY.md §5.
  const std::uint32_t priority = (gate_.enabled() & kDetectUltrasonic) ? d.state.watch & d.selection : 0;
  const auto top = static_cast<std::int32_t>(robot_.max_speed_cm_s);
  const std::uint32_t reach = std::max(d.state.safety_mm, emergency::safety_distance_mm(top, top, cfg_.min_safety_mm, cfg_.safety_mm_per_cm_s));
  const SonarSelection sel{d.selection, priority, priority ? reach + 200 : 0};
  const SonarSelection& had = selection_out_.current();
  if (had.active != sel.active || had.priority != sel.priority || had.listen_mm != sel.listen_mm) selection_out_.publish(sel);
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
void EmergencyModule::log_transitions(const emergency::GateDecision& d) {
  const EmergencyState& s = d.state;
  if (d.tripped)
    log::warn("emergency: {} (sensor {}, safety {} mm){}", word(s.cause), s.sensor, s.safety_mm,
              s.latched ? ", latched until XR" : "");
  else if (s.cause != last_.cause && s.cause != EmergencyCause::none)
    log::info("emergency: {} at rest", word(s.cause));
  if (d.cleared) log::info("emergency: re-enabled");
  if (s.held && !last_.held) log::info("emergency: motion held for data of sensor {}", s.sensor);
  if (d.hold_expired) log::warn("emergency: held motion forgotten (no sensor data)");
  if (d.protective_started) log::info("emergency: protective stop (obstacle in the envelope)");
  if (d.resumed) log::info("emergency: automatic motion resumed, envelope clear");
}

}  // namespace robuter

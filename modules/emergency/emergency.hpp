// SPDX-License-Identifier: GPL-3.0-or-later
// Emergency module: the request-to-move gate between every motion source and the executor.
#pragma once

#include <array>
#include <cstdint>

#include "hal/api/bumpers.hpp"
#include "kernel/config.hpp"
#include "kernel/process.hpp"
#include "modules/emergency/motion_arbiter.hpp"
#include "modules/emergency/motion_gate.hpp"
#include "modules/emergency/ring_envelope.hpp"
#include "modules/topics.hpp"

namespace robuter {

// Tunables of the emergency module that the configuration file does not carry (yet).
struct EmergencyTuning {
  std::uint32_t stale_ticks = 300;       // a watch-dog reading older than this counts as missing, ticks
  std::uint32_t hold_limit_ticks = 500;  // a motion held for data longer than this is forgotten, ticks
};

class EmergencyModule final : public Process {
 public:
  static constexpr std::size_t kMaxSources = 8;  // motion sources the gate arbitrates

  // Registers `link_motion` (serial) and `go_to_motion` (executor) as motion sources.
  EmergencyModule(Blackboard& bb, hal::Bumpers& bumpers, const EmergencyConfig& cfg, const RobotConfig& robot,
                  const EmergencyTuning& tuning = {});
  // The executor, triggered whenever the command changes so it acts in the same tick.
  void set_executor(Process* p) { executor_ = p; }
  // Adds another source of motion requests (gate, doors, planner…); false when full.
  bool add_motion_source(MotionSource source, Reader<MotionRequest> reader);
  // The operator's detections (bumper 1, ultrasonic 2, communication 4); the door crossing may
  // lower them while it is in a door (its DetectionRequest), nothing else.
  void set_enabled(std::uint8_t mask) { base_mask_ = static_cast<std::uint8_t>(mask & kDetectAll); }
  // The detections in force now.
  std::uint8_t enabled() const { return detections(); }
  // Modes the arbiter must know at start-up: the passage finder hands over to the door crossing
  // when aligned ([gate] hand_over); the demonstration drives from start-up ([demo] enabled).
  void set_modes(bool gate_hands_over, bool demo_at_boot) {
    hand_over_ = gate_hands_over;
    demo_at_boot_ = demo_at_boot;
  }
  // The planner may lend the robot to the door crossing at the point before a narrow door of an
  // XQ route ([places] cross_doors; docs/PLACES.md "Doors on a route").
  void set_door_loans(bool on) { door_loans_ = on; }
  // The a-priori map's structure, which explains echoes ([emergency] narrow_arcs, docs/SAFETY.md
  // §13 "Narrowing"); nullptr: none. It must outlive the module.
  void set_known_structure(emergency::KnownStructure* known) { envelope_.set_known_structure(known); }
  // The envelope's grid and pose (tests, figures).
  const emergency::RingEnvelope& envelope() const { return envelope_; }

  bool init(Kernel& k) override;
  void run(Kernel& k) override;

 private:
  // A motion source: a new generation of its topic (Reader::updated) is a new request.
  struct Source {
    MotionSource source = MotionSource::link;  // who publishes there
    Reader<MotionRequest> reader;              // its topic
  };
  // Applies the operator's actions since the last run to the arbiter, in order.
  void take_actions();
  // The passage finder aligned with hand-over on: the door crossing takes the robot.
  void hand_over();
  // The detections in force: the operator's, lowered to the door crossing's only while it owns
  // the robot and is in the door.
  std::uint8_t detections() const;
  // The owner's new request, if any (other sources' requests are seen and dropped).
  void take_requests(emergency::GateInputs& in);
  // Whether the robot has come to rest: the executor's last two postures of different ticks
  // agree (a stopped drive's set-points are zero long before the robot stops braking).
  bool at_rest(const Posture& p);
  // Logs what changed between two verdicts (transitions only, never every tick).
  void log_transitions(const emergency::GateDecision& d);

  hal::Bumpers& bumpers_;
  EmergencyConfig cfg_;
  RobotConfig robot_;
  EmergencyTuning tuning_;
  emergency::MotionGate gate_;
  emergency::MotionArbiter arbiter_;
  emergency::RingEnvelope envelope_;     // the swept envelope and its evidence grid ([emergency] rule = "envelope")
  std::array<Source, kMaxSources> sources_{};
  std::size_t source_count_ = 0;
  Reader<LinkStatus> link_;
  Reader<ServoRequest> servo_;   // ASN/ASF: a new generation is a new request
  Reader<UltrasonicSettings> settings_;
  Reader<UltrasonicRanges> ranges_;
  Reader<Posture> posture_;
  Reader<OperatorEvents> actions_;
  Reader<DetectionRequest> doors_wish_;
  Reader<ModeStatus> doors_status_;
  Reader<ModeStatus> gate_status_;
  Reader<PlannerStatus> planner_status_;  // its door_wish ([places] cross_doors)
  Writer<EmergencyState> state_out_;
  Writer<MotionAuthority> authority_out_;
  Writer<MotionCommand> command_out_;
  Writer<SonarSelection> selection_out_;
  Process* executor_ = nullptr;       // triggered on every new command
  std::uint32_t seen_stop_ = 0;       // LinkStatus.stop_seq last seen
  std::uint32_t seen_reenable_ = 0;   // LinkStatus.reenable_seq last seen
  std::uint32_t seen_actions_ = 0;    // OperatorEvents.count last seen
  std::uint8_t base_mask_ = kDetectAll;  // the operator's detections (configuration, set_enabled)
  bool hand_over_ = false;            // [gate] hand_over
  bool demo_at_boot_ = false;         // [demo] enabled
  bool door_loans_ = false;           // [places] cross_doors
  std::uint32_t door_wish_seen_ = 0;  // PlannerStatus.door_wish last seen
  std::uint32_t loan_doors_runs_ = 0; // the crossing's ModeStatus.runs when the robot was lent to it
  ModeState gate_seen_ = ModeState::off;  // the passage finder's state at the last run
  EmergencyState last_{};             // previous verdict, for transition logs
  Posture pose_{};                    // the executor's posture of the latest tick seen
  bool have_pose_ = false;            // pose_ holds a published posture
  bool moved_ = false;                // the latest posture differs from the one of the tick before
};

}  // namespace robuter

// SPDX-License-Identifier: GPL-3.0-or-later
// The protocol's RobotPort over the blackboards: what a command reads and which topic it writes.
#pragma once

#include <array>
#include <cstdint>

#include "modules/places/place_graph.hpp"
#include "modules/places/route_table.hpp"
#include "modules/executor/posture_units.hpp"
#include "modules/serial/link_settings.hpp"
#include "modules/topics.hpp"
#include "protocol/codec/robot_port.hpp"

namespace robuter {

class Kernel;
class Process;

// The writable handles the serial module (the owner) lends to its port.
struct LinkWriters {
  Writer<MotionRequest> motion;
  Writer<ServoRequest> servo;
  Writer<OdometrySet> odometry;
  Writer<GoToRequest> go_to;
  Writer<UltrasonicSettings> us;
  Writer<LinkStatus> status;
  Writer<ModeRequest> modes;
  Writer<PlannerGoal> goal;   // the planner's goal (XG, XH)
  Writer<OperatorEvents> events;  // the operator's actions for the motion arbiter, in order
  Writer<LocaliseRequest> localise;  // the pose on the map (XA)
};

class LinkPort final : public protocol::RobotPort {
 public:
  LinkPort(Blackboard& bb, LinkWriters& w, const LinkSettings& settings);
  // The kernel, for the clock, XK and the owners' runs (set at init, after the table).
  void attach(Kernel& k);
  // The emergency module, triggered on a stop byte or a motion request so it acts this tick.
  void set_emergency(Process* p) { emergency_process_ = p; }
  // The executor, run before the next line after a command it acts on (ASN, AC, …).
  void set_executor(Process* p) { executor_process_ = p; }
  // The localisation, run before the next line after AC or XA (XW then reads the new pose).
  void set_localise(Process* p) { localise_process_ = p; }

  // Read-your-writes (docs/PROTOCOL.md, "What `ack` means"). A request handed to another
  // module (the emergency module, the executor) starts a wait: both are triggered, and no
  // further line is handled, on any link, until both have run since — the executor after the
  // emergency module's latest command. True while that wait lasts; re-triggers the owners that
  // have not run yet (a trigger the kernel refused for its per-tick bound is asked again).
  bool waiting();
  // Before the line ending with the next byte is handled: when the link has been silent past
  // the communication limit, stamps it now and starts a wait, so that the emergency module
  // judges that line (XR after a communication-loss trip) on a link it knows is alive again.
  // True when the caller must stop before that byte.
  bool revive_link();
  // True once AX was accepted: the serial module flushes the ack, then stops the kernel.
  bool shutdown_requested() const { return shutdown_; }

  // reads
  protocol::Ticks clock() const noexcept override;
  protocol::Posture posture() const noexcept override;
  bool servo_on() const noexcept override;
  protocol::WheelSpeeds wheel_speeds() const noexcept override;
  void ranges(protocol::Ranges& out) const noexcept override;
  std::int32_t us_timeout() const noexcept override;
  protocol::PortResult pan_tilt(protocol::SectorKind kind, protocol::Sectors& out) const noexcept override;
  std::int32_t node_delay() const noexcept override;
  std::int32_t mean_node_time() const noexcept override;
  std::int32_t mean_scan_time() const noexcept override;
  // requests
  protocol::PortResult request_motion(std::int32_t left, std::int32_t right) noexcept override;
  protocol::PortResult set_servo(bool on) noexcept override;
  protocol::PortResult pass_through(std::string_view line) noexcept override;
  protocol::PortResult set_odometry(const protocol::Posture& p) noexcept override;
  protocol::PortResult go_to(const protocol::Posture& target) noexcept override;
  protocol::PortResult request_shutdown() noexcept override;
  protocol::PortResult set_pan_tilt(bool on) noexcept override;
  protocol::PortResult set_gate_finder(bool on) noexcept override;
  protocol::PortResult set_door_crossing(bool on) noexcept override;
  protocol::PortResult set_demo(bool on) noexcept override;
  protocol::PortResult set_sensor_table(const protocol::SensorTable& active) noexcept override;
  protocol::PortResult set_node_delay(std::int32_t ticks) noexcept override;
  protocol::PortResult set_us_timeout(std::int32_t ms) noexcept override;
  protocol::PortResult set_auto_toggle(bool on) noexcept override;
  // link events
  void message_received() noexcept override;
  void immediate_stop() noexcept override;
  // extensions
  protocol::EmergencyStatus emergency() const noexcept override;
  protocol::PortResult reenable() noexcept override;
  protocol::KernelFigures kernel_figures() const noexcept override;
  std::string_view firmware_version() const noexcept override;
  std::uint32_t features() const noexcept override;
  // grid planner (XG, XH, XP, XM)
  protocol::PortResult set_goal(const protocol::Posture& goal, bool with_theta) noexcept override;
  protocol::PortResult cancel_goal() noexcept override;
  protocol::PortResult planner_status(protocol::PlannerReport& out) const noexcept override;
  protocol::PortResult place_here(protocol::PlaceReport& out) const noexcept override;
  protocol::PortResult place_info(std::int32_t number, protocol::PlaceReport& out) const noexcept override;
  protocol::PortResult go_to_place(std::int32_t number, bool explore) noexcept override;
  // Why: the place graph XN, XI and XQ answer from, and its routes (immutable, owned by the
  // firmware); null = none.
  void set_places(const places::PlaceGraph* graph, const places::RouteTable* routes) {
    places_ = graph;
    routes_ = routes;
  }
  protocol::PortResult planner_map(protocol::MapWindow& out) const noexcept override;
  // localisation (XW, XA)
  protocol::PortResult localisation(protocol::LocaliseReport& out) const noexcept override;
  protocol::PortResult set_map_pose(const protocol::Posture& pose, bool global) noexcept override;
  // pan-tilt, passage finder, door crossing, demonstration (XD)
  protocol::PortResult modes(protocol::ModesReport& out) const noexcept override;

 private:
  // True while an emergency is latched: requests to move are refused.
  // The emergency module's admission rule (emergency::admits_motion) says no: refuse with `error`.
  bool latched() const;
  // The pan-tilt module runs and has a unit to talk to (Ap, AG, Ad need it).
  bool has_pan_tilt_unit() const;
  // AG/AT, Ad/Af, XT1/XT0: the mode's module is `present`, `scans` with the pan-tilt; `start` or
  // `stop` goes to the arbiter.
  protocol::PortResult switch_mode(bool present, bool scans, bool on, OperatorAction start, OperatorAction stop) noexcept;
  std::uint64_t tick() const;
  // The robot's pose on its map (the odometry's while no localisation runs): XG, XN, XQ.
  executor::PostureUnits map_pose() const;
  // True once the planner module has published (its process row runs).
  bool planner_running() const { return planner_status_.advertised(); }

  LinkWriters& w_;                         // topics the serial module owns (its writers, lent by reference)
  Reader<Posture> posture_;
  Reader<UltrasonicRanges> ranges_;
  Reader<UltrasonicTiming> timing_;
  Reader<EmergencyState> emergency_;
  Reader<PlannerStatus> planner_status_;
  const places::PlaceGraph* places_ = nullptr;  // [places] file, loaded at start-up; null = none
  const places::RouteTable* routes_ = nullptr;  // its routes as via points (XQ); null = none
  Reader<PlannerMapWindow> planner_map_;
  Reader<PanTiltScan> pan_tilt_scan_;
  Reader<ModeStatus> pan_tilt_status_;
  Reader<ModeStatus> gate_status_;
  Reader<ModeStatus> doors_status_;
  Reader<DemoStatus> demo_status_;
  Reader<Localisation> localisation_;
  const LinkSettings& s_;                  // the serial module's, which outlives the port
  Kernel* kernel_ = nullptr;
  Process* emergency_process_ = nullptr;   // triggered on stop byte and motion requests
  Process* executor_process_ = nullptr;    // triggered on servo and odometry requests
  Process* localise_process_ = nullptr;    // triggered on odometry and map pose requests
  bool localise_runs_ = false;             // the localisation has a row
  bool emergency_runs_ = false;            // the emergency module has a row in the kernel's table
  bool executor_runs_ = false;             // the executor has a row
  Reader<MotionCommand> command_;          // the emergency's command, to know the executor applied it
  // Read-your-writes: a wait for the owners, and their topics' generations when it began.
  bool waiting_ = false;
  bool wait_executor_ = false;             // the wait needs a run of the executor itself (AS, AC)
  std::uint64_t wait_emergency_gen_ = 0;   // EmergencyState generation at the start of the wait
  std::uint64_t wait_posture_gen_ = 0;     // Posture generation at the start of the wait
  // Starts a wait (from now) for the emergency module, and for the executor's own run when
  // `executor`; triggers them.
  void await_owners(bool executor);
  // The emergency module has run since the wait began (or has no row).
  bool emergency_ran() const;
  // The executor has run if the wait needs it, and has applied the emergency's latest command.
  bool executor_done() const;
  // The localisation has taken the latest odometry set (AC) and map pose request (XA).
  bool localise_done() const;
  // Triggers the owners of the current wait that have not done their part yet.
  void trigger_owners() const;
  // Asks the emergency module to judge a new request in this tick.
  void wake_emergency();
  // Hands an operator's action to the motion arbiter (in order) and wakes it.
  void act(OperatorAction a);
  bool shutdown_ = false;                  // AX accepted
  mutable std::array<protocol::ProcessFigures, protocol::kMaxKernelProcesses> figures_{};  // XK storage
};

}  // namespace robuter

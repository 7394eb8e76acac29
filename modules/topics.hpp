// SPDX-License-Identifier: GPL-3.0-or-later
// Every blackboard topic of the firmware: one small struct each, with its owner module.
// docs/ARCHITECTURE.md has the table of writers and readers; keep the two in step.
#pragma once

#include <array>
#include <cstdint>

#include "hal/api/drive.hpp"
#include "kernel/blackboard.hpp"
#include "protocol/codec/vocabulary.hpp"
#include "robot/ring_wiring.hpp"

namespace robuter {

// A new value is told by the topic's generation (Reader::updated(), generation()); no payload
// repeats it. A payload counter is kept only where it says more: several events in one topic
// (LinkStatus.stop_seq and reenable_seq), or a reader echoing
// the generation of another topic it has acted on, so the writer can wait for its effect
// (read-your-writes: Posture.command_seq and odometry_seq, Localisation.request_seq and
// odometry_seq, PlannerStatus.goal_seq).

// Owner modules (each defined in modules/<name>/); naming one in a Topic makes it the writer.
class HeartbeatModule;
class SerialModule;
class UltrasonicModule;
class EmergencyModule;
class ExecutorModule;
class PlannerModule;
class PtuModule;
class GateModule;
class DoorsModule;
class DemoModule;
class LocaliseModule;

// The vocabulary's enums (protocol/codec/vocabulary.hpp): one definition, with the words replies and logs print.
using protocol::DemoPhase;
using protocol::LocaliseState;
using protocol::EmergencyCause;
using protocol::ModeReason;
using protocol::ModeState;
using protocol::PlannerState;
using protocol::kDetectAll;         // the detection bits of EmergencyState::enabled and the gate
using protocol::kDetectBumper;
using protocol::kDetectComm;
using protocol::kDetectUltrasonic;

inline constexpr int kSensors = robot::kRingSensors;  // ultrasonic ring sensors, numbered 1..24

// Proof of life of the kernel.
struct Heartbeat {
  std::uint64_t beats = 0;  // heartbeats since start
  std::uint64_t tick = 0;   // tick of the last beat
};

// Where the robot is and what reaches its motors (executor).
struct Posture {
  std::int32_t x = 0;           // 0.1 mm, odometry frame
  std::int32_t y = 0;           // 0.1 mm
  std::int32_t theta = 0;       // 0.01 degree, in (-18000, 18000]
  bool servo = false;           // servo (brake released, motors powered)
  std::int32_t left = 0;        // wheel speed set-point that reached the drive, cm/s
  std::int32_t right = 0;       // cm/s
  std::uint64_t tick = 0;       // tick of the odometry read
  hal::DriveHealth drive_health = hal::DriveHealth::ok;  // the drive's health as its backend sees it
  std::uint32_t command_seq = 0;  // MotionCommand's generation applied by this run (the link's read-your-writes)
  std::uint32_t odometry_seq = 0; // OdometrySet's generation applied so far: the odometry frame's number (AC
                                  // starts a new one; the link's read-your-writes, the localisation's frame)
};

// Who asked for a motion (the emergency module arbitrates, newest request wins).
enum class MotionSource : std::uint8_t { link, go_to, gate, doors, planner, demo };

// A request to move: wheel speeds wanted by one source. Never reaches the motors directly.
struct MotionRequest {
  std::int32_t left = 0;        // cm/s
  std::int32_t right = 0;       // cm/s
  std::uint64_t tick = 0;       // tick of the request (each request is a publication: a repeat of the same speeds counts)
};

// Servo on/off asked by the operator (ASN / ASF).
struct ServoRequest {
  bool on = false;              // wanted servo state
};

// Odometry posture to set (AC).
struct OdometrySet {
  std::int32_t x = 0;           // 0.1 mm
  std::int32_t y = 0;           // 0.1 mm
  std::int32_t theta = 0;       // 0.01 degree
};

// Go-to-posture target (AW); the executor drives there through the emergency gate.
struct GoToRequest {
  std::int32_t x = 0;           // 0.1 mm
  std::int32_t y = 0;           // 0.1 mm
  std::int32_t theta = 0;       // 0.01 degree
  bool active = false;          // false cancels
};

// How the operator set the ultrasonic ring (UT, UD, Ut, Uu; defaults from the configuration).
struct UltrasonicSettings {
  std::uint32_t user_table = 0xFFFFFF;  // bit s-1 = sensor s active (UT)
  std::uint32_t node_delay_ticks = 3;   // delay between two nodes, ticks (UD)
  std::uint32_t timeout_ms = 33;        // echo time-out, ms (Ut)
  bool auto_toggle = false;             // only the watch-dog sensors fire (Uu)
};

// The ring's latest ranges (us).
struct UltrasonicRanges {
  std::array<std::uint16_t, kSensors> mm{};      // range of sensor s at [s-1], mm; 0 = inactive / none
  std::array<std::uint64_t, kSensors> read_tick{};  // tick each range was read
  std::uint32_t scans = 0;                       // full passes over the active nodes
  std::uint32_t no_echo = 0;                     // bit s-1: sensor s heard no echo within mm (the firing's reach:
                                                 // the time-out range, or less for a shortened firing)
  std::uint64_t tick = 0;                        // tick of the latest read
};

// Timing of the ring (USN, USS).
struct UltrasonicTiming {
  std::uint32_t mean_node_ticks = 0;   // mean time to read one node, ticks
  std::uint32_t mean_scan_ticks = 0;   // mean time to read all six nodes, ticks (0: not measured)
};

// Which sensors the ring fires, decided by the emergency module (watch-dog set, auto-toggle).
struct SonarSelection {
  std::uint32_t active = 0xFFFFFF;     // bit s-1 = sensor s fires
  std::uint32_t priority = 0;          // bit s-1 = sensor s watches where the robot goes: its node
                                       // fires first and most often (0: stopped, the seed's order)
  std::uint32_t listen_mm = 0;         // range the safety check needs from a priority firing, mm
                                       // (its time-out is shortened to it; 0 = the full time-out)
};

// The emergency module's verdict.
struct EmergencyState {
  bool held = false;            // motion held until a watch-dog sensor has data
  bool latched = false;         // stopped by an emergency, waiting for a re-enable
  EmergencyCause cause = EmergencyCause::none;  // the cause (kept while latched)
  std::uint8_t enabled = kDetectAll;  // detections on: kDetect* bits (bumper 1, ultrasonic 2, communication 4)
  std::int32_t main_sensor = 0; // sensor in the direction of motion (0 when stopped)
  std::uint32_t watch = 0;      // watch-dog sensor set, bit s-1 = sensor s
  std::uint64_t tick = 0;       // tick of the verdict
  std::uint32_t trips = 0;      // emergencies that stopped the robot since start (count)
  bool clearable = false;       // latched and the cause is gone: a re-enable (XR) now clears it
  std::uint32_t safety_mm = 0;  // safety distance in force, mm (0 when stopped)
  std::int32_t sensor = 0;      // sensor that tripped (obstacle) or is awaited (held), 0 none
  bool envelope = false;        // obstacle rule in force: true = swept envelope, false = the seed's watch sets
  bool protective = false;      // protective stop: obstacle evidence in the envelope (resets itself, no XR)
  std::uint8_t granted_pct = 0; // granted share of the requested speeds, % (100 = all, 0 = none or stopped)
  std::uint32_t protective_stops = 0;  // protective stops since start (count; not emergencies, not in trips)
};

// What the executor is allowed to send to the motors: the only path to a non-zero speed.
struct MotionCommand {
  std::int32_t left = 0;        // cm/s
  std::int32_t right = 0;       // cm/s
  bool stop = true;             // true: zero speeds and servo off (emergency)
  MotionSource source = MotionSource::link;  // who asked for the granted speeds
};

// Life of the command links (serial).
struct LinkStatus {
  std::uint64_t last_message_tick = 0;  // tick of the last complete line, valid or not (the seed's stamp: SAFETY.md SAF-2)
  std::uint32_t stop_seq = 0;           // immediate stop bytes received
  std::uint32_t reenable_seq = 0;       // re-enable requests (XR)
  std::uint32_t links_open = 0;         // links with a client attached
  std::uint32_t devices_lost = 0;       // serial devices lost (hang-up, I/O error, node removed), count
  std::uint32_t devices_back = 0;       // serial devices re-opened after a loss, count
  std::uint64_t lines_discarded = 0;    // lines dropped unexecuted: their reply could not be queued (a client
                                        // that does not read), count
  std::uint32_t sessions = 0;           // pty client sessions started, count
};

// The pan-tilt scanning switched from the link (Ap/Ag; each is a publication: a new Ap restarts a
// failed unit). The other modes (AG/AT, Ad/Af, XT) start and end through the arbiter (`authority`).
struct ModeRequest {
  bool pan_tilt = false;        // pan-tilt scanning on
};

// ---- pan-tilt scanner, passage finder, door crossing, demonstration (docs/DOORS.md) ----

inline constexpr int kPanTiltSectors = 72;  // 5° sectors, sector i looking 5i° counter-clockwise from the front

// The robot's odometry posture when a pan-tilt sector was measured.
struct SectorPose {
  std::int32_t x = 0;      // 0.1 mm
  std::int32_t y = 0;      // 0.1 mm
  std::int32_t theta = 0;  // 0.01 degree
};

// The pan-tilt's 72-sector scan (seed pt_values, fvalues, dvalues), sector by sector as swept.
struct PanTiltScan {
  std::array<std::int32_t, kPanTiltSectors> raw{};          // corrected range from the transducer face, mm (BP)
  std::array<std::int32_t, kPanTiltSectors> filtered{};     // after the spike filter, mm (BF)
  std::array<std::int32_t, kPanTiltSectors> differences{};  // filtered[i+1] − filtered[i], mm (BD)
  std::array<std::uint64_t, kPanTiltSectors> read_tick{};   // tick each sector was fired, 0 = never
  std::array<SectorPose, kPanTiltSectors> pose{};           // odometry posture at each firing
  std::array<std::int32_t, kPanTiltSectors> direction{};    // where each reading looked, 0.01° from forward, counter-clockwise
  std::uint32_t sweeps = 0;                                 // passes from one end to the other, count
  std::uint32_t readings = 0;                               // firings read back, count
  std::uint64_t tick = 0;                                   // tick of the latest reading
  bool fitted = false;                                      // the module has a unit to talk to (a port, or the
                                                            // simulated unit): false → Ap, AG, Ad answer no-unit
};

// A mode module's report.
struct ModeStatus {
  ModeState state = ModeState::off;     // see ModeState
  ModeReason reason = ModeReason::none; // see ModeReason (none unless failed)
  std::uint32_t runs = 0;               // times the mode was started, count
  std::uint64_t since_tick = 0;         // tick the current state began
  std::int32_t width_mm = 0;            // gate: estimated passage width, mm (0: none)
  std::uint32_t duration_ticks = 0;     // gate/doors: length of the last run, ticks
  std::uint64_t tick = 0;               // tick of the report
};

// A navigation goal for the grid planner (XG / XH), in the odometry frame.
struct PlannerGoal {
  static constexpr std::size_t kMaxVias = 63;  // points before the goal (a route over places, XQ)
  // A point the navigation passes through before the goal (the route's doors, docs/PLACES.md).
  struct Via {
    std::int32_t x = 0;         // 0.1 mm
    std::int32_t y = 0;         // 0.1 mm
    std::int32_t theta = 0;     // 0.01 degree: turn to it there when has_theta (facing a door)
    bool has_theta = false;
    bool spin = false;          // XQ <n> 1 (exploration): a place's centre, turn a full circle and scan there
  };
  std::int32_t x = 0;           // 0.1 mm
  std::int32_t y = 0;           // 0.1 mm
  std::int32_t theta = 0;       // 0.01 degree, final heading when has_theta
  bool has_theta = false;       // turn to theta once at (x, y)
  bool active = false;          // false cancels (XH)
  std::uint8_t vias = 0;        // points in `via` driven through, in order, before (x, y) (XG: 0)
  std::uint16_t place = 0;      // XQ: the goal place's number (1-based); 0 for XG
  std::array<Via, kMaxVias> via{};  // the first `vias` are used
};

// The grid planner's report (XP).
struct PlannerStatus {
  PlannerState state = PlannerState::idle;  // see PlannerState
  std::int32_t goal_x = 0;      // goal being served, 0.1 mm
  std::int32_t goal_y = 0;      // 0.1 mm
  std::uint32_t path_mm = 0;    // length of the last path found, mm (0: none)
  std::uint32_t prefix_mm = 0;  // length of the part being followed, mm
  std::uint32_t plans = 0;      // plans made for this goal (the first plus the replans)
  std::uint32_t scans = 0;      // stops to scan for this goal
  std::uint32_t plan_us = 0;    // execution time of the last plan's search, µs (thread CPU time)
  std::uint32_t run_us_max = 0; // longest activation of the planner since start, µs (thread CPU time)
  std::uint32_t goal_seq = 0;   // PlannerGoal's generation being served: the goal's number (plan pictures' names)
  std::uint8_t vias = 0;        // the goal's via points (a route over places, XQ; 0 for XG)
  std::uint8_t via_next = 0;    // via points passed so far (== vias: driving to the goal itself)
  std::uint16_t goal_place = 0; // XQ: the goal place's number; 0 for XG
  std::uint32_t door_wish = 0;  // bumped when the planner, at the point before a narrow door, asks for the door crossing ([places] cross_doors)
  std::int32_t map_x0_mm = 0;   // lower-left corner of the planner's map window, odometry frame, mm
  std::int32_t map_y0_mm = 0;   // mm (the window moves for a goal off it: docs/PLANNER.md)
  std::uint64_t tick = 0;       // tick of the report
};

// Seed 003's text view of the planner's map around the robot (XM).
struct PlannerMapWindow {
  static constexpr int kSide = 41;  // cells per side (odd: the robot's cell is the centre)
  std::array<char, kSide * kSide> cells{};  // '.', '#', ' ', 'P'; row 0 = top (largest y)
  std::int32_t center_x = 0;    // centre of the robot's cell, 0.1 mm (odometry frame)
  std::int32_t center_y = 0;    // 0.1 mm
  std::int32_t cell_mm = 0;     // cell side, mm (0: no map yet)
  std::uint64_t tick = 0;       // tick of the rendering
};

// The demonstration course's report (seed dem.c; [demo] enabled).
struct DemoStatus {
  ModeState state = ModeState::off;  // off (not enabled), running, finished, failed
  ModeReason reason = ModeReason::none;  // why it failed (no_landmark, shutdown), else none
  DemoPhase phase = DemoPhase::wait; // where the course is (wait, out, turn, lane, align, advance, circle, done, failed)
  std::uint32_t laps = 0;            // laps completed (each ends at the recalibration point)
  std::int32_t side_mm = 0;          // last calibration: side sensors to the boxes (ERRO), mm
  std::int32_t radius_mm = 0;        // the half-circle radius that reading gave, mm
  std::uint64_t lap_tick = 0;        // tick the last lap ended
  std::uint64_t tick = 0;            // tick of the report
};

// ---- the motion arbiter (modules/emergency/motion_arbiter.*; docs/SAFETY.md §1) ----

// An operator's command that bears on who drives, as the links took it.
enum class OperatorAction : std::uint8_t {
  motion,         // AM (AM 0 0 too)
  go_to,          // AW with a target
  servo,          // ASN or ASF (any servo request ends a motion at the gate)
  stop_byte,      // the immediate stop byte 0x18
  halt,           // XH
  start_gate,     // AG
  stop_gate,      // AT
  start_doors,    // Ad
  stop_doors,     // Af
  start_planner,  // XG
  start_demo,     // XT1
  stop_demo,      // XT0
};

// One operator action and when it was taken.
struct OperatorEvent {
  OperatorAction action = OperatorAction::motion;  // what
  std::uint64_t tick = 0;                          // when, ticks
};

// The operator's actions in the order the links took them (a ring: event n is at n % capacity).
struct OperatorEvents {
  static constexpr std::uint32_t kCapacity = 32;   // events kept between two arbiter runs
  std::array<OperatorEvent, kCapacity> ring{};     // the latest events
  std::uint32_t count = 0;                         // events since start
};

inline constexpr std::size_t kMotionSources = 6;   // MotionSource values

// Who may drive, decided by the arbiter in the emergency module.
struct MotionAuthority {
  MotionSource owner = MotionSource::link;              // link / go_to: the operator; else that automatic mode
  std::array<std::uint32_t, kMotionSources> runs{};     // per source: times the robot was handed to it
  std::array<ModeReason, kMotionSources> ended{};       // per source: why its last run ended (none: never ended)
  MotionSource lent_by = MotionSource::link;            // the mode whose run goes on while it lends the robot to the owner (the planner at a narrow door: docs/PLACES.md); link: none
  std::uint8_t detections = kDetectAll;                 // emergency detections in force: kDetect* bits
  std::uint64_t tick = 0;                               // tick of the decision
};

// The operator's pose on the map for the localisation (XA), or a global search.
struct LocaliseRequest {
  bool global = false;          // search the whole map (XA without a pose)
  std::int32_t x = 0;           // 0.1 mm, map frame
  std::int32_t y = 0;           // 0.1 mm
  std::int32_t theta = 0;       // 0.01 degree
};

// Where the robot is on its map (localise), and the map frame's place against the odometry's:
// the estimate `map` was made for the odometry posture `odometry`, so the robot's map pose now is
// map ∘ odometry⁻¹ ∘ (the posture now) — modules/localise/map_frame.hpp, the one place that composes it.
struct Localisation {
  LocaliseState state = LocaliseState::off;  // see LocaliseState
  std::int32_t x = 0;             // the estimate, 0.1 mm, map frame
  std::int32_t y = 0;             // 0.1 mm
  std::int32_t theta = 0;         // 0.01 degree
  std::int32_t major_mm = 0;      // the position's 1-sigma ellipse: semi-major axis, mm
  std::int32_t minor_mm = 0;      // semi-minor axis, mm
  std::int32_t axis = 0;          // direction of the major axis, 0.01 degree
  std::int32_t sigma_theta = 0;   // the heading's standard deviation, 0.01 degree
  std::uint8_t cluster_pct = 0;   // share of the weight in the estimate's cluster, %
  std::uint16_t particles = 0;    // particles kept
  std::uint32_t steps = 0;        // filter steps since start
  // The correction in force (the last tracking estimate, or the start pose): map pose of the
  // odometry posture (odo_x, odo_y, odo_theta).
  std::int32_t map_x = 0;         // 0.1 mm, map frame
  std::int32_t map_y = 0;         // 0.1 mm
  std::int32_t map_theta = 0;     // 0.01 degree
  std::int32_t odo_x = 0;         // 0.1 mm, odometry frame
  std::int32_t odo_y = 0;         // 0.1 mm
  std::int32_t odo_theta = 0;     // 0.01 degree
  std::uint32_t odometry_seq = 0; // Posture.odometry_seq the odometry pose belongs to
  std::uint32_t request_seq = 0;  // LocaliseRequest's generation taken (the link's read-your-writes after XA)
  std::uint32_t run_us_max = 0;   // longest activation since start, µs (thread CPU time)
  std::uint32_t scouts_fired = 0; // times a scout's evidence drew particles to it since start (docs/LOCALISATION.md, "Scouts")
  std::uint64_t tick = 0;         // tick of the report
};

// The door crossing's wish for lowered detections while it crosses (seed doors(): emerg.on = BUMPER).
struct DetectionRequest {
  bool lower = false;           // lower the detections while the crossing is in the door
  std::uint8_t keep = kDetectBumper;  // detections kept then: kDetect* bits
};

// The firmware's shared state: one Topic per struct, owner fixed by the type.
struct Blackboard {
  Topic<Heartbeat, HeartbeatModule> heartbeat;
  // serial (command links)
  Topic<MotionRequest, SerialModule> link_motion;
  Topic<ServoRequest, SerialModule> servo_request;
  Topic<OdometrySet, SerialModule> odometry_set;
  Topic<GoToRequest, SerialModule> go_to;
  Topic<UltrasonicSettings, SerialModule> us_settings;
  Topic<LinkStatus, SerialModule> link_status;
  Topic<ModeRequest, SerialModule> modes;
  Topic<OperatorEvents, SerialModule> operator_events;
  // us (ultrasonic ring)
  Topic<UltrasonicRanges, UltrasonicModule> ranges;
  Topic<UltrasonicTiming, UltrasonicModule> us_timing;
  // emergency
  Topic<EmergencyState, EmergencyModule> emergency;
  Topic<MotionCommand, EmergencyModule> motion_command;
  Topic<SonarSelection, EmergencyModule> sonar_selection;
  Topic<MotionAuthority, EmergencyModule> authority;
  // executor
  Topic<Posture, ExecutorModule> posture;
  Topic<MotionRequest, ExecutorModule> go_to_motion;
  // planner (goal from the link, XG / XH; requests, report and map view from the planner)
  Topic<PlannerGoal, SerialModule> planner_goal;
  Topic<MotionRequest, PlannerModule> planner_motion;
  Topic<PlannerStatus, PlannerModule> planner_status;
  Topic<PlannerMapWindow, PlannerModule> planner_map;
  // pan-tilt scanner, passage finder, door crossing, demonstration (requests through the gate)
  Topic<PanTiltScan, PtuModule> pan_tilt_scan;
  Topic<ModeStatus, PtuModule> pan_tilt_status;
  Topic<MotionRequest, GateModule> gate_motion;
  Topic<ModeStatus, GateModule> gate_status;
  Topic<MotionRequest, DoorsModule> doors_motion;
  Topic<ModeStatus, DoorsModule> doors_status;
  Topic<DetectionRequest, DoorsModule> doors_detections;
  Topic<MotionRequest, DemoModule> demo_motion;
  Topic<DemoStatus, DemoModule> demo_status;
  // localisation (the operator's pose on the map from the link; the estimate from the module)
  Topic<LocaliseRequest, SerialModule> localise_request;
  Topic<Localisation, LocaliseModule> localisation;

  // Calls f(name, topic) for every topic above, in order (the start-up claim check, the tests
  // that keep docs/ARCHITECTURE.md's topic table in step).
  template <typename F>
  void for_each_topic(F&& f) const {
    each_topic(*this, f);
  }
  template <typename F>
  void for_each_topic(F&& f) {
    each_topic(*this, f);
  }

 private:
  template <typename Board, typename F>
  static void each_topic(Board& bb, F& f) {
    f("heartbeat", bb.heartbeat);
    f("link_motion", bb.link_motion);
    f("servo_request", bb.servo_request);
    f("odometry_set", bb.odometry_set);
    f("go_to", bb.go_to);
    f("us_settings", bb.us_settings);
    f("link_status", bb.link_status);
    f("modes", bb.modes);
    f("operator_events", bb.operator_events);
    f("ranges", bb.ranges);
    f("us_timing", bb.us_timing);
    f("emergency", bb.emergency);
    f("motion_command", bb.motion_command);
    f("sonar_selection", bb.sonar_selection);
    f("authority", bb.authority);
    f("posture", bb.posture);
    f("go_to_motion", bb.go_to_motion);
    f("planner_goal", bb.planner_goal);
    f("planner_motion", bb.planner_motion);
    f("planner_status", bb.planner_status);
    f("planner_map", bb.planner_map);
    f("pan_tilt_scan", bb.pan_tilt_scan);
    f("pan_tilt_status", bb.pan_tilt_status);
    f("gate_motion", bb.gate_motion);
    f("gate_status", bb.gate_status);
    f("doors_motion", bb.doors_motion);
    f("doors_status", bb.doors_status);
    f("doors_detections", bb.doors_detections);
    f("demo_motion", bb.demo_motion);
    f("demo_status", bb.demo_status);
    f("localise_request", bb.localise_request);
    f("localisation", bb.localisation);
  }
};

}  // namespace robuter

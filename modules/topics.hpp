// Every blackboard topic of the firmware: one small struct each, with its owner module.
// docs/ARCHITECTURE.md has the table of writers and readers; keep the two in step.
#pragma once

#include <array>
#include <cstdint>

#include "kernel/blackboard.hpp"
#include "robot/ring_wiring.hpp"

namespace robuter {

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
  std::uint8_t drive_health = 0; // hal::DriveHealth of the drive as a number (0 ok)
};

// Who asked for a motion (the emergency module arbitrates, newest request wins).
enum class MotionSource : std::uint8_t { link, go_to, gate, doors, planner, demo };

// A request to move: wheel speeds wanted by one source. Never reaches the motors directly.
struct MotionRequest {
  std::int32_t left = 0;        // cm/s
  std::int32_t right = 0;       // cm/s
  std::uint32_t seq = 0;        // bumped on every request (a repeat of the same speeds counts)
  std::uint64_t tick = 0;       // tick of the request
};

// Servo on/off asked by the operator (ASN / ASF).
struct ServoRequest {
  bool on = false;              // wanted servo state
  std::uint32_t seq = 0;        // bumped on every request
};

// Odometry posture to set (AC).
struct OdometrySet {
  std::int32_t x = 0;           // 0.1 mm
  std::int32_t y = 0;           // 0.1 mm
  std::int32_t theta = 0;       // 0.01 degree
  std::uint32_t seq = 0;        // bumped on every request
};

// Go-to-posture target (AW); the executor drives there through the emergency gate.
struct GoToRequest {
  std::int32_t x = 0;           // 0.1 mm
  std::int32_t y = 0;           // 0.1 mm
  std::int32_t theta = 0;       // 0.01 degree
  bool active = false;          // false cancels
  std::uint32_t seq = 0;        // bumped on every request
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
  std::uint32_t no_echo = 0;                     // bit s-1: sensor s heard no echo (mm = time-out range)
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
};

// Why an emergency holds. The last three come from the drives' bus (docs/CAN.md).
enum class EmergencyCause : std::uint8_t {
  none, bumper, obstacle, comm_loss, stop_byte, motion_timeout, drive_fault, other,
  heartbeat_lost,  // a drive stopped sending its heartbeat
  bus_passive,     // the drives' CAN bus went error-passive
  bus_off,         // the CAN controller went bus-off
};

// The emergency module's verdict.
struct EmergencyState {
  bool held = false;            // motion held until a watch-dog sensor has data
  bool latched = false;         // stopped by an emergency, waiting for a re-enable
  EmergencyCause cause = EmergencyCause::none;  // the cause (kept while latched)
  std::uint8_t enabled = 7;     // detections on: bumper 1, ultrasonic 2, communication 4
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
  std::uint32_t seq = 0;        // bumped on every decision
  MotionSource source = MotionSource::link;  // who asked for the granted speeds
};

// Life of the command links (serial).
struct LinkStatus {
  std::uint64_t last_message_tick = 0;  // tick of the last well-formed command
  std::uint32_t stop_seq = 0;           // immediate stop bytes received
  std::uint32_t reenable_seq = 0;       // re-enable requests (XR)
  std::uint32_t links_open = 0;         // links with a client attached
  std::uint32_t devices_lost = 0;       // serial devices lost (hang-up, I/O error, node removed), count
  std::uint32_t devices_back = 0;       // serial devices re-opened after a loss, count
};

// Modes switched from the link (Ap/Ag, AG/AT, Ad/Af).
struct ModeRequest {
  bool pan_tilt = false;        // pan-tilt scanning on
  bool gate = false;            // passage finder on
  bool doors = false;           // door crossing on
  std::uint32_t seq = 0;        // bumped on every change
  std::uint32_t pan_tilt_seq = 0;  // bumped by every Ap / Ag
  std::uint32_t gate_seq = 0;      // bumped by every AG / AT
  std::uint32_t doors_seq = 0;     // bumped by every Ad / Af
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
};

// What the pan-tilt, passage-finder or door-crossing module is doing (XD).
enum class ModeState : std::uint8_t {
  off,        // not asked for (or ended and reset)
  starting,   // pan-tilt: start-up sequence; doors: waiting for a fresh scan
  scanning,   // pan-tilt: sweeping and firing
  searching,  // gate: stopped, waiting for a fresh scan to find the passage
  moving,     // gate: manoeuvring to the passage's centre line
  aligned,    // gate: stopped on the centre line facing the passage (done)
  crossing,   // doors: moving through
  waiting,    // doors: blocked on both sides, waiting for fresh readings
  leaving,    // doors: through; driving on until the body is clear
  crossed,    // doors: done
  failed,     // ended without success: see the reason
  running,    // demonstration: driving the course
  finished,   // demonstration: every lap driven, stopped (done)
};

// Why a mode failed or ended.
enum class ModeReason : std::uint8_t {
  none,
  no_unit,        // pan-tilt: no port configured or it could not be opened
  unit_silent,    // pan-tilt: the unit stopped answering
  unit_garbage,   // pan-tilt: the unit's replies are not the protocol's
  unit_refused,   // pan-tilt: the unit refused a command ("!")
  unit_lost,      // pan-tilt: its port went away
  no_passage,     // gate: no passage locked within the time-out
  cannot_align,   // gate: no alignment within the allowed manoeuvres
  cant_cross,     // doors: blocked on both sides for longer than the wait
  emergency,      // an emergency stopped the robot
  operator_motion,// a newer motion request from the link took over
  scanner,        // the pan-tilt failed under the mode
  cancelled,      // AT / Af (or Ag while a mode needed the scanner)
  link_lost,      // doors: every command link closed
  timeout,        // doors: the crossing took longer than its limit
  shutdown,       // the firmware stopped
  no_landmark,    // demonstration: the calibration boxes were not found in time
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
  std::int32_t x = 0;           // 0.1 mm
  std::int32_t y = 0;           // 0.1 mm
  std::int32_t theta = 0;       // 0.01 degree, final heading when has_theta
  bool has_theta = false;       // turn to theta once at (x, y)
  bool active = false;          // false cancels (XH)
  std::uint32_t seq = 0;        // bumped on every request
};

// What the grid planner is doing.
enum class PlannerState : std::uint8_t {
  idle,         // no goal yet
  scanning,     // stopped, waiting for fresh ring data
  planning,     // a plan is due this activation
  moving,       // following the visible prefix of the path
  reached,      // at the goal (within the tolerance)
  unreachable,  // no path to the goal on the current map (or the goal cell is an obstacle)
  blocked,      // the robot's own place is an obstacle on the map: no plan starts from here
  outside,      // the robot is off the planner's map
  stopped,      // an emergency, or another motion source, ended the navigation
  cancelled,    // XH
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
  std::uint32_t goal_seq = 0;   // PlannerGoal.seq being served
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
  std::uint8_t phase = 0;            // demo::Phase as a number (wait, out, turn, lane, align, advance, circle, done, failed)
  std::uint32_t laps = 0;            // laps completed (each ends at the recalibration point)
  std::int32_t side_mm = 0;          // last calibration: side sensors to the boxes (ERRO), mm
  std::int32_t radius_mm = 0;        // the half-circle radius that reading gave, mm
  std::uint64_t lap_tick = 0;        // tick the last lap ended
  std::uint64_t tick = 0;            // tick of the report
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
  // us (ultrasonic ring)
  Topic<UltrasonicRanges, UltrasonicModule> ranges;
  Topic<UltrasonicTiming, UltrasonicModule> us_timing;
  // emergency
  Topic<EmergencyState, EmergencyModule> emergency;
  Topic<MotionCommand, EmergencyModule> motion_command;
  Topic<SonarSelection, EmergencyModule> sonar_selection;
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
  Topic<MotionRequest, DemoModule> demo_motion;
  Topic<DemoStatus, DemoModule> demo_status;
};

}  // namespace robuter

// SPDX-License-Identifier: GPL-3.0-or-later
// Value types exchanged between the codec and the robot port (posture, ranges, statuses).
#pragma once

#include <array>
#include <bitset>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "protocol/codec/limits.hpp"
#include "protocol/codec/vocabulary.hpp"

namespace robuter::protocol {

using Ticks = std::int64_t;                           // clock ticks of 10 ms since start
using Ranges = std::array<std::int32_t, kSensorCount>;    // ultrasonic ranges, mm, 0 = none
using Sectors = std::array<std::int32_t, kSectorCount>;   // pan-tilt values, mm (or mm difference)
using SensorTable = std::bitset<kSensorCount>;        // bit k set = sensor k+1 active

// Where the robot believes it is (odometry).
struct Posture {
  std::int32_t x = 0;      // 0.1 mm
  std::int32_t y = 0;      // 0.1 mm
  std::int32_t theta = 0;  // 0.01 degree, in (-18000, 18000]
};

// The wheel speeds in force (for the status stream).
struct WheelSpeeds {
  std::int32_t left = 0;   // cm/s
  std::int32_t right = 0;  // cm/s
};

// Which of the three pan-tilt arrays a B request reads.
enum class SectorKind : std::uint8_t {
  raw,          // BP: ranges as measured
  filtered,     // BF: after the spike filter
  differences,  // BD: differences of adjacent filtered values
};

// The port's answer to a request that changes something; anything but ok becomes `error`.
enum class PortResult : std::uint8_t {
  ok,                 // done or accepted: `ack`
  refused_emergency,  // an emergency holds or the emergency module refused it
  not_permitted,      // disabled by configuration
  out_of_range,       // a value beyond what this robot accepts
  unavailable,        // equipment or module not fitted / not running
  busy,               // excluded by what the robot is doing now
  no_unit,            // needs the pan-tilt unit, and the robot has none (Ap, AG, Ad)
};

// The emergency module's state, as XE reports it.
struct EmergencyStatus {
  bool held = false;                          // motion held waiting for sensor data
  bool latched = false;                       // an emergency stopped the robot and is not cleared
  EmergencyCause cause = EmergencyCause::none;  // why (none when not latched)
  std::uint8_t enabled = 0;                   // detectors on: kDetect* bits
  std::uint8_t granted_pct = 100;             // share of the requested speeds granted now, % (100: no limit)
  bool envelope = true;                       // obstacle rule: true = swept envelope, false = the seed's watch sets
  bool protective = false;                    // a protective stop is in force (resets itself; no XR)
};

// One kernel process's figures for XK.
struct ProcessFigures {
  std::string_view name;          // process name, one word (sanitised in the reply)
  std::uint64_t activations = 0;  // runs since start
  std::uint64_t overruns = 0;     // runs longer than their time budget
  std::uint64_t slips = 0;        // periodic runs started a period or more late
  std::int64_t mean_us = 0;       // mean execution time, microseconds
  std::int64_t max_us = 0;        // longest execution, microseconds
};

// The kernel's figures for XK; `processes` points into port-owned storage.
struct KernelFigures {
  std::uint64_t ticks = 0;        // ticks run since start
  std::int64_t max_late_us = 0;   // worst tick start lateness, microseconds
  std::int64_t p99_late_us = 0;   // 99th percentile of tick lateness, microseconds
  std::span<const ProcessFigures> processes;  // at most kMaxKernelProcesses are listed
};

// One mode's state for XD (docs/PROTOCOL.md, XD); the reply prints the vocabulary's words.
struct ModeReport {
  bool absent = false;                   // its module is not running: XD reads "absent none"
  ModeState state = ModeState::off;      // what it is doing
  ModeReason reason = ModeReason::none;  // why it failed or ended (none otherwise)
};

// The pan-tilt scanner, passage finder, door crossing and demonstration for XD.
struct ModesReport {
  ModeReport pan_tilt;              // the scanner (Ap / Ag)
  ModeReport gate;                  // the passage finder (AG / AT)
  ModeReport doors;                 // the door crossing (Ad / Af)
  std::int64_t sweeps = 0;          // pan-tilt passes completed since start
  std::int64_t width_mm = 0;        // passage width the finder estimated, mm (0: none)
  std::int64_t crossing_ticks = 0;  // length of the last door crossing, ticks (0: none)
  ModeReport demo;                  // the demonstration course ([demo] enabled): off, running, finished, failed
  DemoPhase demo_phase = DemoPhase::wait;  // its phase (XD reads "none" while it is off or absent)
  std::int64_t demo_laps = 0;       // laps it has completed
};

// The grid planner's report for XP.
struct PlannerReport {
  PlannerState state = PlannerState::idle;  // what it is doing
  std::int32_t goal_x = 0;        // goal, 0.1 mm
  std::int32_t goal_y = 0;        // 0.1 mm
  std::int64_t path_mm = 0;       // length of the last path found, mm (0: none)
  std::int64_t prefix_mm = 0;     // length of the part being followed, mm
  std::int64_t replans = 0;       // plans after the first for this goal
  std::int64_t scans = 0;         // stops to scan for this goal
  std::int64_t plan_us = 0;       // execution time of the last plan's search, microseconds
  std::int64_t max_us = 0;        // longest activation of the planner since start, microseconds
};

// The localisation's report for XW (docs/LOCALISATION.md, "XW").
struct LocaliseReport {
  LocaliseState state = LocaliseState::off;  // what it is doing
  std::int32_t x = 0;             // estimated pose on the map, 0.1 mm
  std::int32_t y = 0;             // 0.1 mm
  std::int32_t theta = 0;         // 0.01 degree, (-18000, 18000]
  std::int32_t major_mm = 0;      // the position's 1-sigma ellipse: semi-major axis, mm
  std::int32_t minor_mm = 0;      // semi-minor axis, mm
  std::int32_t axis = 0;          // direction of the major axis, 0.01 degree, (-9000, 9000]
  std::int32_t sigma_theta = 0;   // the heading's standard deviation, 0.01 degree
  std::int32_t cluster_pct = 0;   // share of the particles' weight in the estimate's cluster, %
  std::int32_t particles = 0;     // particles kept now
  std::int64_t steps = 0;         // filter steps since start
};

// One place of the place graph, for XN (the robot's place) and XI (any place).
struct PlaceReport {
  static constexpr std::size_t kMaxNeighbours = 16;  // listed in XI (more are cut)
  std::int32_t count = 0;            // places in the graph
  std::int32_t number = 0;           // this place, 1-based in the file's order; 0: none (XN outside every place)
  std::string_view name{};           // its name (valid while the line is handled); empty when none
  std::int32_t centre_x = 0;         // its centre, 0.1 mm (the odometry frame)
  std::int32_t centre_y = 0;         // 0.1 mm
  std::int32_t neighbours = 0;       // places one door away (may exceed what is listed)
  std::array<std::int32_t, kMaxNeighbours> neighbour{};  // their numbers, in the order of the doors
};

// The planner's map around the robot for XM: seed 003's characters, top row first.
struct MapWindow {
  std::int32_t side = 0;          // cells per side
  std::int32_t cell_mm = 0;       // cell side, mm
  std::int32_t center_x = 0;      // centre of the middle cell (the robot's), 0.1 mm
  std::int32_t center_y = 0;      // 0.1 mm
  std::string_view cells;         // side x side of '.', '#', ' ', 'P'; port-owned, valid while handled
};

// Optional equipment and features of this robot, for XV's capability list.
inline constexpr std::uint32_t kFeaturePanTilt = 1;      // pan-tilt scanner fitted (Ap, BP, ...)
inline constexpr std::uint32_t kFeatureGate = 2;         // passage finder (AG/AT)
inline constexpr std::uint32_t kFeatureDoors = 4;        // door crossing (Ad/Af)
inline constexpr std::uint32_t kFeaturePassThrough = 8;  // AY enabled by configuration
inline constexpr std::uint32_t kFeatureGoTo = 16;        // AW go-to-posture
inline constexpr std::uint32_t kFeaturePlanner = 32;     // XG/XH/XP/XM grid planner running

}  // namespace robuter::protocol

// SPDX-License-Identifier: GPL-3.0-or-later
// The robot's configuration: one TOML file, defaults equal to the seed's constants.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "robot/robot_model.hpp"

namespace robuter {

// Kernel timing and real-time set-up.
struct KernelConfig {
  std::uint32_t tick_us = 10'000;   // tick length, µs (seed: 10 ms)
  bool realtime = false;            // ask for SCHED_FIFO at start-up
  int rt_priority = 50;             // SCHED_FIFO priority, 1..99
  bool lock_memory = false;         // mlockall(MCL_CURRENT | MCL_FUTURE) at start-up
  std::string log_level = "info";   // debug, info, warn, error, off
};

// Overrides of one row of the process table, by process name.
struct ProcessOverride {
  std::string name;                        // process name (must exist in the table)
  std::optional<std::uint32_t> period;     // ticks
  std::optional<std::uint32_t> offset;     // ticks
  std::optional<int> priority;             // higher runs first within a tick
  std::optional<std::uint32_t> budget_us;  // µs
  int line = 0;                            // line of its table in the file, for errors
  int period_line = 0;                     // line of its period key (0: not given), for errors
  int offset_line = 0;                     // line of its offset key
  int budget_line = 0;                     // line of its budget_us key
};

// The robot the firmware believes it drives: the body and wheels of robot/robot_model.hpp, in
// the configuration's units (robot_model() turns the whole configuration into the model).
struct RobotConfig {
  std::uint32_t length_mm = robot::mm_u(robot::kRobuter.body.length);         // rectangle length along x, mm
  std::uint32_t width_mm = robot::mm_u(robot::kRobuter.body.width);           // rectangle width, mm
  std::uint32_t axle_to_front_mm = robot::mm_u(robot::kRobuter.body.axle_to_front);  // wheel axle to the front face, mm
  std::uint32_t wheel_base_mm = robot::mm_u(robot::kRobuter.wheels.base);     // distance between the drive wheels (DBW), mm
  std::uint32_t max_speed_cm_s = robot::mm_u(robot::kRobuter.wheels.max_speed) / 10;  // largest wheel speed accepted, cm/s
  std::uint32_t max_accel_cm_s2 = robot::mm_u(robot::kRobuter.wheels.max_accel) / 10; // wheel acceleration limit, cm/s²
  std::uint32_t max_decel_cm_s2 = robot::mm_u(robot::kRobuter.wheels.max_decel) / 10; // braking deceleration, cm/s²
};

// Ultrasonic ring timing (us.c).
struct SonarConfig {
  std::uint32_t node_delay_ticks = 3;    // delay between firing two nodes, ticks
  std::uint32_t timeout_ms = 33;         // echo time-out, ms (≈ 5 m at 300 m/s)
  std::uint32_t sound_speed_m_s = 300;   // calibrated speed of sound, m/s
  std::string schedule = "watch";        // firing order while moving: "watch" (where the robot goes
                                         // first and most often) or "seed" (node order, as stopped)
  std::uint32_t moving_timeout_ms = 20;  // echo time-out of the rotation's firings between two watch
                                         // firings while moving, ms (≈ 3 m; 0 = timeout_ms)
};

// Emergency watchdog (emerg.c).
struct EmergencyConfig {
  std::uint32_t mask = 7;                    // enabled detections: bumper 1, ultrasonic 2, communication 4
  std::uint32_t comm_limit_ticks = 18'000;   // link silence that trips, ticks (3 min)
  std::uint32_t min_safety_mm = 220;         // smallest safety distance, mm
  std::uint32_t safety_mm_per_cm_s = 10;     // safety distance per cm/s of the faster wheel, mm
  std::uint32_t motion_timeout_ms = 0;       // stop when no motion command for this long while moving; 0 = off
  bool auto_toggle = false;                  // only the watch-dog sensors fire
  bool latch = true;                         // a tripped emergency holds until re-enabled
  std::string rule = "envelope";             // obstacle rule: "envelope" (swept body, docs/SAFETY.md §13) or "seed" (watch-dog sets)
  std::uint32_t margin_mm = 30;              // envelope: clearance kept around the body, mm
  std::uint32_t creep_cm_s = 20;             // envelope: fastest wheel where only the blind near field is unknown, cm/s
  std::uint32_t free_age_ms = 3000;          // envelope: free space older than this is unknown again, ms
  std::uint32_t single_echo_ms = 3000;       // envelope: one echo's evidence that no later echo marks counts this long (0: for ever), ms
  bool narrow_arcs = true;                   // envelope: an echo meeting the a-priori map's walls marks only them and what no recent cone saw through (SAFETY.md §13)
  std::uint32_t protective_clear_ms = 1000;  // envelope: an automatic mode resumes after this long clear, ms
  std::uint32_t reaction_ms = 110;           // envelope: from a decision to the next one reaching the drive, ms
};

// What operators may do over the link.
struct PermissionsConfig {
  bool pass_through = false;                 // AY accepted at all
  std::vector<std::string> pass_through_allow;  // AY command prefixes allowed when enabled
  bool shutdown = true;                      // AX accepted
};

// The pan-tilt unit and its two sonars (seed ptu.c, ptu.h; docs/DOORS.md).
struct PanTiltConfig {
  std::string port;                          // the unit's serial device, empty = no unit (robuterd --ptu-port)
  std::uint32_t baud = 9600;                 // its rate, bit/s
  std::string parity = "none";               // its parity: none, even, odd (docs/HARDWARE.md)
  std::uint32_t stop_bits = 1;               // its stop bits, 1 or 2
  std::string flow_control = "none";         // none, hardware (RTS/CTS), software (XON/XOFF)
  std::uint32_t retry_ms = 500;              // a lost port is looked for this often, ms
  std::int32_t min_position = -1755;         // one end of the sweep, positions (−90.2°)
  std::int32_t max_position = 1655;          // the other end, positions (85.0°)
  std::uint32_t speed = 1500;                // pan speed, positions/s (SPEED)
  std::uint32_t acceleration = 6000;         // pan acceleration, positions/s² (PA6000)
  std::uint32_t fire_tolerance_centideg = 100;  // fire within this of a multiple of 5°, 0.01° (seed ±1°)
  std::uint32_t poll_period_ticks = 3;       // the unit's position is asked this often, ticks (seed 30 ms)
  std::uint32_t reply_timeout_ticks = 20;    // an unanswered command times out after this, ticks
  std::uint32_t max_failures = 3;            // consecutive time-outs or bad replies that fail the unit
  std::uint32_t cap_mm = 2491;               // readings above this (and no echo) count as this, mm (PAN_TIME_OUT_DIST)
  std::uint32_t offset_mm = 46;              // calibration: measured = scale · real + offset, mm
  std::uint32_t scale_permille = 960;        // calibration scale, ‰ (0.96)
  std::uint32_t filter_high_mm = 2300;       // spike filter: neighbours above this are high, mm (MAX)
  std::uint32_t filter_drop_mm = 1000;       // spike filter: a spike is below high − this, mm
  std::int32_t pivot_x_mm = robot::mm(robot::kRobuter.pan_tilt.pivot_x);  // pan axis ahead of the wheel axle (negative: behind), mm
  std::uint32_t box_width_mm = robot::mm_u(2.0 * robot::kRobuter.pan_tilt.face_offset);  // between the two transducer faces (BOX_WIDTH), mm
  std::uint32_t beam_half_angle_centideg = static_cast<std::uint32_t>(robot::centideg(robot::kRobuter.pan_tilt.half_angle));  // half-angle of a pan-tilt sonar's beam, 0.01°
};

// The passage finder (seed gate.c, gate.h; docs/DOORS.md).
struct GateConfig {
  std::uint32_t margin_mm = 300;             // a jump of the differences above this marks a corner (MARGIN)
  std::uint32_t max_gap_sectors = 8;         // a passage spans fewer far sectors than this (in_door < 8)
  std::uint32_t min_mm = 700;                // a corner this close ends the approach (MIN)
  std::uint32_t max_mm = 2300;               // a corner reading at or beyond this is no corner (MAX)
  std::uint32_t speed_cm_s = 5;              // driving speed (Va), cm/s
  std::uint32_t turn_cm_s = 2;               // turning speed of each wheel (Va/2), cm/s
  std::uint32_t timeout_ticks = 1000;        // no passage locked for this long: give up (TIMEOUT), ticks
  std::uint32_t stage_mm = 300;              // aligned with the front face this far from the passage, mm
  std::uint32_t lateral_tolerance_mm = 30;   // aligned when the axle is this close to the centre line, mm
  std::uint32_t heading_tolerance_centideg = 200;  // and the heading this close to the passage's normal, 0.01°
  std::uint32_t max_manoeuvres = 6;          // manoeuvres allowed before giving up
  std::uint32_t stall_ticks = 500;           // a manoeuvre the robot has not moved in for this long backs off, ticks
  std::uint32_t back_off_mm = 250;           // how far it backs off before scanning again, mm
  bool hand_over = false;                    // start the door crossing when aligned (the seed's door = ON); off: it lowers the sonar without a 2nd command (SAFETY.md §1)
};

// The door crossing (seed doors.c, doors.h; docs/DOORS.md). The body and the pan-tilt's place on
// it (PAN_X/Y_POSITION, BOX_WIDTH): the robot model ([robot], [ptu] pivot_x_mm, box_width_mm).
struct DoorsConfig {
  std::uint32_t safety_mm = 35;              // clearance kept from obstacles (SAFETY_DIST), mm
  std::uint32_t max_dist_mm = 1500;          // a side all beyond this: through the door (MAX_DIST), mm
  std::uint32_t time_before_move_ticks = 500;  // blocked on both sides this long: can't cross (TIME_BEFORE_MOVE)
  std::uint32_t forward_cm_s = 2;            // speed going straight, cm/s
  std::uint32_t back_cm_s = 1;               // speed of the wheel that backs off in a turn, cm/s
  std::uint32_t entered_mm = 1500;           // both sides seen closer than this: inside the door, mm
  std::uint32_t beside_mm = 300;             // and those echoes this close to abreast of the pan axis, mm
  std::uint32_t exit_mm = 400;               // driven on after "through" so the rear clears the door, mm
  std::uint32_t max_age_ticks = 600;         // pan-tilt readings older than this are ignored, ticks
  std::uint32_t same_echo_mm = 20;           // neighbouring sectors this close in range see the same echo, mm
  std::uint32_t echo_spread_percent = 0;     // an echo is judged over this share of its bearing uncertainty, %
  std::uint32_t timeout_ticks = 30000;       // a crossing longer than this fails, ticks (0: no limit)
  std::uint32_t emergency_mask = 1;          // detections kept on while crossing (bumper 1)
};

// The grid planner (modules/planner): its map, robot model, sonar use and motion.
struct PlannerModuleConfig {
  std::int32_t map_origin_x_mm = -8000;  // lower-left corner of the map, odometry frame, mm
  std::int32_t map_origin_y_mm = -8000;  // mm
  std::uint32_t map_width_mm = 16000;    // map extent along x, mm
  std::uint32_t map_height_mm = 16000;   // map extent along y, mm
  std::uint32_t cell_mm = 50;            // cell side, mm (seed 000: 5 cm)
  std::string footprint = "rectangle";   // "rectangle" (the body, with heading) or "disc"
  std::uint32_t disc_radius_mm = 780;    // disc footprint radius, mm (axle to a front corner)
  std::uint32_t margin_mm = 0;           // clearance added all round the body to translate, mm
  std::uint32_t turn_clearance_mm = 250; // more clearance needed to turn in place, mm
  std::uint32_t heading_slices = 16;     // heading slices over a half turn (rectangle)
  std::uint32_t hit_threshold = 2;       // net sonar hits that make a cell an obstacle
  std::uint32_t initial_count = 0;       // count a never-seen cell starts from when a beam first touches it (seed 003: 5)
  std::string map_file;                  // a-priori map ("robuter-map 1", odometry frame), resolved against the configuration's folder; empty = none
  int map_file_line = 0;                 // line of planner.map_file in the configuration (0: not written)
  std::array<int, 5> geometry_lines{};   // lines of map_origin_x_mm, map_origin_y_mm, map_width_mm, map_height_mm, cell_mm in the configuration (0: not written)
  std::uint32_t scan_passes = 2;         // full ring passes waited for at each stop
  std::uint32_t beam_range_mm = 2500;    // readings marked up to this range, mm
  std::uint32_t beam_half_angle_centideg = static_cast<std::uint32_t>(robot::centideg(robot::kRobuter.ring.half_angle));  // ring sonar cone half-angle, 0.01° (0: axis only)
  std::uint32_t follow_range_mm = 1500;  // the path is followed this far before a new scan, mm
  std::uint32_t goal_tolerance_mm = 100; // arrived within this distance of the goal, mm
  std::uint32_t drive_speed_cm_s = 20;   // fastest wheel while driving, cm/s
  std::uint32_t turn_speed_cm_s = 10;    // fastest wheel while turning in place, cm/s
};

// Why: the largest map (cells) the planner may be sized for, about 200 MB: checked for the
// configured map and for an a-priori map file alike.
long long planner_cell_limit(const PlannerModuleConfig& p);

// A serial command link ([links.serial]; docs/HARDWARE.md).
// [places]: seed 003's topological map (docs/PLACES.md).
struct PlacesConfig {
  std::string file;   // place graph ("robuter-places 1", odometry frame), resolved against the configuration's folder; empty = none
  int file_line = 0;  // line of places.file in the configuration (0: not written)
  std::string grids_dir;  // folder of the place grids saved after each scan (seed 003's drawsec()), resolved like file; empty = none
  bool load_grids = false;   // at start-up, the grids_dir's saved grids are the planner's memory of the floor (docs/PLACES.md)
  bool cross_doors = false;  // XQ: at a narrow door the planner lends the robot to the door crossing (which lowers the detections in the door): off unless configured
};

// Localisation on the robot's map (modules/localise, docs/LOCALISATION.md).
struct LocaliseConfig {
  bool enabled = false;               // run the particle filter on the map (planner.map_file or the place graph's walls)
  std::uint32_t min_particles = 200;  // KLD-sampling keeps at least this many
  std::uint32_t max_particles = 2000; // and at most this many (every buffer is this size, from start-up)
  std::uint32_t particles_per_run = 200;  // particles weighed per activation (the bound on its work: docs/LOCALISATION.md)
  std::uint32_t traces_per_run = 64;      // and of them, at most this many with the map's promises traced
  std::uint32_t initial_sigma_mm = 100;   // spread of the start pose (the odometry's, a state file's, XA's), mm
  std::uint32_t initial_sigma_deg = 5;    // and of its heading, degrees
  bool report_corrected = false;      // BO, BV and the XS stream report the map pose instead of the odometry's
  std::string state_file;             // the last estimate, kept across restarts (written off the periodic path); empty = none
  std::uint64_t seed = 1;             // the filter's random draws (a run is reproducible)
};

struct SerialLinkConfig {
  std::string device;                        // its device, empty = none (robuterd --serial overrides)
  std::uint32_t baud = 9600;                 // line rate, bit/s (robuterd --baud overrides)
  std::string parity = "none";               // none, even, odd
  std::uint32_t stop_bits = 1;               // 1 or 2
  std::string flow_control = "none";         // none, hardware (RTS/CTS), software (XON/XOFF)
  std::uint32_t retry_ms = 500;              // a lost device is looked for this often, ms
};

// Command links configured in the file ([links]).
struct LinksConfig {
  SerialLinkConfig serial;                   // [links.serial]
  bool stop_when_clients_leave = false;      // stop the robot when a pty's last client closes it (ARCOS does)
};

// Digital inputs on the Linux GPIO character device ([hardware.gpio]; docs/HARDWARE.md).
struct GpioConfig {
  std::string chip;                          // e.g. /dev/gpiochip0; empty = bumpers from the backend
  std::vector<std::uint32_t> bumper_lines;   // line offsets of the bumpers; bit i of `pressed` = entry i
  std::vector<std::uint32_t> input_lines;    // further digital inputs (generic), line offsets
  bool active_low = true;                    // a line reads 0 (low) when its contact is closed
  std::uint32_t debounce_us = 0;             // kernel debounce period, µs (0 = none)
  int line = 0;                              // line of chip in the file, for errors
};

// The demonstration course (seed dem.c, annex A; docs/DOORS.md).
struct DemoConfig {
  bool enabled = false;                      // drive the course from start-up
  std::uint32_t distx_mm = 1200;             // front sensor to the front box when calibrated (DISTX 12000 × 0.1 mm)
  std::uint32_t disty_mm = 1000;             // side sensors to the calibration boxes on the lane (DISTY)
  std::uint32_t raio_mm = 1000;              // radius of the half-circles (RAIO)
  std::uint32_t straight_mm = 2500;          // the straight leg after the recalibration point
  std::uint32_t lane_mm = 2100;              // the lane driven back before calibrating
  std::uint32_t speed_cm_s = 20;             // cruising wheel speed
  std::uint32_t slow_cm_s = 10;              // approach and calibration circle speed
  std::uint32_t align_cm_s = 1;              // the turning wheel while aligning
  std::uint32_t sensor_a = 17;               // side sensors that must read alike (seed text: 17 and 19)
  std::uint32_t sensor_b = 19;               // the other one (seed text: 19)
  std::uint32_t front_sensor = 1;            // the sensor that measures DISTX
  std::uint32_t align_tolerance_mm = 5;      // side readings this close count as alike
  std::uint32_t calibration_readings = 3;    // each calibration figure is the median of this many fresh readings (1: the seed's one)
  std::uint32_t laps = 6;                    // laps, then stop (the seed ended its program after n > 5: DOORS.md DM-2); 0 = for ever
  std::uint32_t calibration_timeout_ticks = 6000;  // align + advance longer than this: failed no-landmark, ticks (0: no limit)
};

// Which hardware backends robuterd uses without --sim (docs/CAN.md).
struct HardwareConfig {
  std::string drive = "none";                // "none" or "can": the drives on CAN (CiA 402)
  std::string sonar = "none";                // "none" or "can": the ultrasonic nodes on CAN
};

// The CAN bus, its CiA 402 drives and ultrasonic nodes (docs/CAN.md).
struct CanConfig {
  std::string interface = "can0";            // SocketCAN interface name
  std::uint32_t left_node = 1;               // CANopen node id of the left wheel's drive, 1..127
  std::uint32_t right_node = 2;              // node id of the right wheel's drive
  std::uint32_t sonar_node_base = 16;        // node id of ring node 0; node n is base + n (7: pan-tilt channel)
  std::uint32_t counts_per_rev = 16384;      // encoder increments per wheel revolution (gearbox included)
  std::uint32_t wheel_diameter_mm = 200;     // drive wheel diameter, mm
  bool left_invert = false;                  // positive velocity turns the left wheel backwards
  bool right_invert = true;                  // … the right wheel (mounted mirrored)
  std::uint32_t heartbeat_ms = 100;          // heartbeat producer time written to the drives, ms
  std::uint32_t heartbeat_timeout_ms = 350;  // a node silent this long is lost, ms
  std::uint32_t sdo_timeout_ms = 100;        // an unanswered SDO write is repeated after this, ms
  std::uint32_t fault_reset_ms = 1000;       // a drive in fault gets a fault reset this often, ms
  std::uint32_t host_node = 127;             // node id of robuterd's own heartbeat (0x700 + id), 1..127
  std::uint32_t host_heartbeat_ms = 50;      // robuterd's heartbeat period (sent only while every row runs on time), ms
  std::uint32_t drive_watchdog_ms = 300;     // consumer heartbeat time written to the drives (0x1016:01), ms; 0 = off
};

struct SimSection;  // kernel/sim_section.hpp

struct Config {
  std::string source = "(defaults)";         // file the configuration came from
  KernelConfig kernel;
  RobotConfig robot;
  SonarConfig sonar;
  EmergencyConfig emergency;
  PermissionsConfig permissions;
  PlannerModuleConfig planner;
  PlacesConfig places;                       // [places]
  LocaliseConfig localise;                   // [localise]
  PanTiltConfig ptu;
  GateConfig gate;
  DoorsConfig doors;
  LinksConfig links;                         // [links.serial]
  GpioConfig gpio;                           // [hardware.gpio]
  DemoConfig demo;
  HardwareConfig hardware;                   // [hardware] drive, sonar
  CanConfig can;                             // [can]
  std::vector<ProcessOverride> processes;    // [process.NAME] tables
  std::optional<std::vector<std::string>> enabled_modules;  // [modules] enabled; none = all
  std::shared_ptr<const SimSection> sim;     // [sim]: the simulated robot's own parameters, null when absent
};

// A configuration problem: where and what.
struct ConfigError {
  std::string file;   // path of the file
  int line = 0;       // 1-based line, 0 when not tied to one
  std::string key;    // dotted key, empty when not tied to one
  std::string what;   // the problem, for people
  // "file:line: key 'a.b': what".
  std::string message() const;
};

// The robot model the configuration describes: robot::kRobuter with [robot]'s body and wheels and
// [ptu]'s mount (pivot_x_mm, box_width_mm, beam_half_angle_centideg).
robot::RobotModel robot_model(const Config& c);

// Loads and validates a configuration file; the first problem found is returned.
std::optional<ConfigError> load_config(const std::string& path, Config& out);
// Parses configuration text (the file name is used in errors only).
std::optional<ConfigError> parse_config(std::string_view text, const std::string& file, Config& out);

}  // namespace robuter

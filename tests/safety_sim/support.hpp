// SPDX-License-Identifier: GPL-3.0-or-later
// Shared helpers of the whole-firmware safety acceptance tests: worlds, replies, geometry, monitors.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hal/sim/footprint.hpp"
#include "hal/sim/world.hpp"
#include "kernel/config.hpp"
#include "modules/firmware/sim_firmware.hpp"

namespace robuter::test::safety_sim {

// A world file written for one test (the firmware loads worlds from files); removed with the object.
class TempWorld {
 public:
  explicit TempWorld(const std::string& toml);
  ~TempWorld();
  TempWorld(const TempWorld&) = delete;
  TempWorld& operator=(const TempWorld&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string dir_;   // private temporary folder
  std::string path_;  // the .toml file in it
};

// Parses a TOML world with the firmware's robot footprint; the loader's message when it is refused
// (so a generator can retry before a firmware is built on it).
std::optional<std::string> check_world(const std::string& toml, const Config& cfg = Config{});

// A configuration whose process table holds only the safety core and what it needs (simulator,
// links, ring, emergency, executor, heartbeat): for tests that build thousands of firmwares, where
// the start-up of modules that stay idle there (a planner's map) would dominate the run time.
Config core_config();

// The default configuration on the seed's obstacle rule (the watch-dog sets, docs/SAFETY.md §2–§3):
// the acceptance tests of §12 that measure that rule (wall stop, reaction, watch sets, obstacle
// trips, auto-toggle) run on it; the envelope (§13) has its own.
Config seed_rule_config(Config c = Config{});
// The same configuration on the envelope's obstacle rule (docs/SAFETY.md §13; not yet the default).
Config envelope_rule_config(Config c = Config{});

// The simulator's body geometry for a firmware configuration (as SimRobot builds it).
sim::RobotGeometry geometry(const Config& cfg = Config{});

// Shortest distance from the robot's body at `pose` to any obstacle edge, m (0 when touching or
// overlapping): the true clearance, independent of the bumper's 1 mm tolerance. `where`, if given,
// receives the point of the body nearest to the obstacle, in the robot frame (m).
double body_clearance(const sim::World& world, const sim::RobotGeometry& g, const sim::Pose& pose,
                      sim::Vec2* where = nullptr);

// The same limited to the edges within `reach` metres of the body's bounding box (a grid query,
// for checks on every tick); `reach` when none is that near. `scratch` must be prepared for the
// world's edges.
double body_clearance_near(const sim::World& world, const sim::RobotGeometry& g, const sim::Pose& pose, double reach,
                           sim::GridScratch& scratch, sim::Vec2* where = nullptr);

// `BO` reply: S <x> <y> <theta> <servo> <clock>.
struct BoReply {
  int x = 0, y = 0, theta = 0, servo = 0;  // 0.1 mm, 0.01°, 0/1
  long long clock = 0;                     // ticks
};
std::optional<BoReply> parse_bo(const std::optional<std::string>& reply);

// `XE` reply: E <held> <latched> <cause> <enabled> <clock> <granted-%> <rule> <protective>.
struct XeReply {
  int held = 0, latched = 0;
  std::string cause;
  int enabled = 0;
  long long clock = 0;
  int granted_pct = 0;   // share of the request granted, %
  std::string rule;      // envelope or seed
  int protective = 0;    // protective stop in force
};
std::optional<XeReply> parse_xe(const std::optional<std::string>& reply);

// The wheel speeds the drive was last commanded (SimDrive::commanded), cm/s.
struct Wheels {
  std::int32_t left = 0, right = 0;
  bool zero() const { return left == 0 && right == 0; }
};
Wheels commanded(SimFirmware& fw);

// The sensor numbers set in a ring mask (sensor 1 = bit 0), for messages: "{1,5,12}".
std::string sensor_list(std::uint32_t mask);

// Checks the safety invariants after every tick of a firmware: no non-zero speed at the drive
// while the emergency is latched, no non-zero speed the gate did not grant, and — while the
// ultrasonic detection is on — no contact. Install with attach(); counts and the first violation
// are kept for the report.
class SafetyMonitor {
 public:
  // Attaches to `fw` (replaces its tick observer); `world` is the firmware's simulated world.
  void attach(SimFirmware& fw);
  void check();  // one tick's checks (attach() calls it after every tick)

  std::uint64_t ticks = 0;               // ticks checked
  std::uint64_t latched_ticks = 0;       // ticks with the emergency latched
  std::uint64_t moving_ticks = 0;        // ticks with a non-zero commanded speed
  std::uint64_t us_on_ticks = 0;         // ticks with the ultrasonic detection on
  std::uint64_t latched_moving = 0;      // violations: non-zero speed while latched
  std::uint64_t ungranted = 0;           // violations: non-zero speed other than the granted one
  std::uint64_t contact_us_on = 0;       // violations: ticks of a contact (bumper pressed / body touching)
                                         // with the ultrasonic detection on that began with it on, or
                                         // with the drive still moving
  std::uint64_t contact_us_off = 0;      // ticks of contacts that began with it off (allowed: the door
                                         // crossing lowers it; the bumper's trip then restores it while
                                         // the body still touches, which is not a contact the ring let happen)
  std::uint64_t longest_disagreement = 0;  // longest run of ticks with the drive not at the gate's verdict
  double min_clearance_us_on = 1e9;      // smallest true clearance seen with ultrasonic on, m
  std::string first_violation;           // description of the first violation (empty: none)
  // The first contact with the ultrasonic detection on, for the diagnosis.
  Wheels contact_motion{};               // the last non-zero speeds the drive had before it, cm/s
  bool contact_while_stopping = false;   // the drive was already commanded to zero
  sim::Vec2 contact_point = sim::Vec2::Zero();  // body point touching, robot frame, m

  std::uint64_t violations() const { return latched_moving + ungranted + contact_us_on; }

 private:
  // Records a violation; keeps the first description.
  void violation(std::uint64_t& counter, const std::string& what);

  SimFirmware* fw_ = nullptr;
  sim::RobotGeometry geom_{};
  sim::GridScratch scratch_;             // grid queries of the clearance
  Wheels last_moving_{};                 // the last non-zero speeds at the drive
  bool touching_ = false;                // the bumper was pressed at the last tick
  bool touch_began_us_on_ = false;       // the ultrasonic detection was on when the contact began
  std::uint64_t disagreement_ = 0;       // current run of ticks with the drive not at the verdict
};

}  // namespace robuter::test::safety_sim

// SPDX-License-Identifier: GPL-3.0-or-later
// The simulated Robuter: differential drive with acceleration limits, exact arc integration,
// contact with the world (bumper, no tunnelling), and odometry with optional seeded errors.
#pragma once

#include <cstdint>

#include "hal/sim/footprint.hpp"
#include "hal/sim/rng.hpp"
#include "hal/sim/trail.hpp"

namespace robuter::sim {

// How fast the wheels may go and change speed.
struct DriveLimits {
  double max_wheel_speed = robot::kRobuter.wheels.max_speed;  // commands are clamped to ±this, m/s
  double max_accel = robot::kRobuter.wheels.max_accel;        // tread acceleration while a wheel speeds up, m/s²
  double max_decel = 2.0 * robot::kRobuter.wheels.max_accel;  // tread deceleration while a wheel slows down, m/s²
};

// Differences between what the encoders report and how the robot really moves. All zero (the
// default) makes the odometry exact.
struct OdometryErrors {
  double scale_left = 0.0;        // left encoder reads (1 + this) × its wheel travel, fraction
  double scale_right = 0.0;       // right encoder scale error, fraction
  double wheel_base_error = 0.0;  // odometry assumes (odometry_wheel_base or wheel_base) + this, m
  double noise = 0.0;             // random encoder error, m per √m of wheel travel
  double slip_mean = 0.0;         // mean fraction of wheel travel lost to slip on the floor
  double slip_sigma = 0.0;        // deviation of that fraction, drawn per wheel per sub-step
  std::uint64_t seed = 1;         // seed of the error generator (same seed, same run)
};

// Everything that configures a Robot.
struct RobotParams {
  RobotGeometry geometry;              // body and wheel geometry
  DriveLimits limits;                  // speed and acceleration limits
  OdometryErrors odometry;             // encoder and slip errors
  double odometry_wheel_base = 0.0;    // wheel base the odometry integrates with (what the
                                       // firmware believes), m; 0 = the true geometry's
  double contact_tolerance = 0.001;    // the bumper is pressed within this distance of an edge, m
  double max_substep_travel = 0.02;    // no body point moves further between contact checks, m
  double max_ramp_substep = 0.005;     // longest sub-step while wheel speeds ramp, s
  std::size_t trail_capacity = 8192;   // trail points kept for pictures
  double trail_spacing = 0.05;         // distance between recorded trail points, m
};

// One simulated robot in one world. Pure and single-threaded: the caller commands wheel speeds
// and calls step(dt). No allocation after construction.
class Robot {
 public:
  // The world must outlive the robot. The start pose is not checked (loaders check theirs).
  Robot(const World& world, const RobotParams& params, const Pose& start);

  // Commands wheel tread speeds, m/s (clamped to the limit); they are reached at the
  // acceleration limits.
  void command(const WheelSpeeds& speeds);
  // The firmware's units: wheel speeds in cm/s.
  void command_cm_s(double left, double right);

  // Advances the simulation by dt seconds.
  void step(double dt);

  // Moves the robot to `pose` at rest (tests, scenario set-up); odometry is reset to it too.
  void place(const Pose& pose);
  // Re-seeds odometry to `pose` (the firmware's "set posture").
  void set_odometry(const Pose& pose) { odom_ = pose; }

  const Pose& pose() const { return pose_; }              // true pose in the world
  const Pose& odometry() const { return odom_; }          // what the encoders integrate to
  const WheelSpeeds& wheel_speeds() const { return actual_; }    // current wheel speeds, m/s
  const WheelSpeeds& commanded() const { return command_; }      // last command, m/s
  bool bumper() const { return bumper_; }                 // body within contact tolerance
  bool blocked() const { return blocked_; }               // last step ended on a contact
  double time() const { return time_; }                   // simulated seconds since start
  double travelled() const { return travelled_; }         // path length of the axle midpoint, m
  const Trail& trail() const { return trail_; }           // recent axle positions
  const RobotParams& params() const { return params_; }
  const World& world() const { return world_; }

 private:
  // Moves for tau seconds at constant wheel speeds; false when a contact stopped the motion.
  bool advance(double left, double right, double tau);
  // Adds one segment of wheel travel to the odometry estimate.
  void integrate_odometry(double dl, double dr);
  // Records the position in the trail when far enough from the last point.
  void record_trail();
  // Fastest any body point moves at these wheel speeds, m/s.
  double max_point_speed(double left, double right) const;

  const World& world_;            // the world; outlives the robot
  RobotParams params_;            // configuration
  Pose pose_;                     // true pose
  Pose odom_;                     // odometry estimate
  WheelSpeeds command_;           // commanded wheel speeds, m/s
  WheelSpeeds actual_;            // current wheel speeds, m/s
  bool bumper_ = false;           // contact within tolerance
  bool blocked_ = false;          // last step stopped on a contact
  double time_ = 0.0;             // simulated time, s
  double travelled_ = 0.0;        // distance travelled by the axle midpoint, m
  double corner_radius_ = 0.0;    // farthest body point from the axle midpoint, m
  Vec2 last_trail_ = Vec2::Zero();// last recorded trail point, m
  Trail trail_;                   // recent positions
  Rng rng_;                       // odometry error generator
  GridScratch scratch_;           // grid query scratch
};

}  // namespace robuter::sim

// SPDX-License-Identifier: GPL-3.0-or-later
// Simulator configuration from TOML: robot geometry and limits, odometry errors, sonar
// behaviour, and overrides of rows of the ring layout table and of the pan-tilt mount.
#pragma once

#include <toml++/toml.h>

#include <cstdint>
#include <filesystem>
#include <string_view>

#include "hal/sim/result.hpp"
#include "hal/sim/robot.hpp"
#include "hal/sim/sonar_layout.hpp"
#include "hal/sim/sonar_timing.hpp"

namespace robuter::sim {

// Everything the simulated robot's hardware is made of.
struct SimConfig {
  RobotParams robot;                                     // body, drive, odometry errors
  SonarParams ring = default_ring_params();              // ring sonar behaviour
  RingLayout layout = default_ring_layout();             // ring sensor mounting
  RingTiming timing;                                     // ring firing timing
  std::uint64_t sonar_seed = 1;                          // seed of the sonar noise generator
  SonarParams pan_tilt = default_pan_tilt_params();      // pan-tilt sonar behaviour
  PanTiltMount pan_tilt_mount;                           // pan-tilt position
};

// Applies a TOML table to `base` and returns the result. Keys (all optional; lengths in metres,
// angles in degrees, times in milliseconds as their names say):
//   [robot]    length width axle_to_front wheel_base max_wheel_speed max_accel max_decel
//              contact_tolerance max_substep_travel trail_spacing
//   [odometry] scale_left scale_right wheel_base_error noise slip_mean slip_sigma seed
//   [sonar]    model ("ideal", "stress", "realistic": sets the effects below, read first)
//              half_angle_deg timeout_ms sound_speed min_range max_incidence_deg
//              max_incidence_smooth_deg max_incidence_rough_deg noise_sigma
//              noise_relative spurious_probability dropout_probability spurious_in_window
//              multipath crosstalk scale offset no_echo node_delay_ms seed
//   [[sonar.sensor]] number (1..24, required) x y direction_deg (a mounting error; the node
//              wiring is the robot model's)
//   [pan_tilt] x y sensor_offset and the [sonar] behaviour keys (except node_delay_ms, seed)
// Unknown keys are errors (with file and line). `prefix` names the tables in messages ("sim."
// for the [sim] section of robuterd's configuration).
Result<SimConfig> apply_sim_config(const toml::table& table, std::string_view file,
                                   SimConfig base = {}, std::string_view prefix = "");

// Parses TOML text and applies it (see apply_sim_config).
Result<SimConfig> parse_sim_config(std::string_view text, std::string_view file,
                                   SimConfig base = {});

// Reads a TOML file and applies it.
Result<SimConfig> load_sim_config(const std::filesystem::path& path, SimConfig base = {});

}  // namespace robuter::sim

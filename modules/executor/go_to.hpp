// SPDX-License-Identifier: GPL-3.0-or-later
// Go-to-posture controller (AW): turn towards (x, y), drive there, turn to theta. Pure.
#pragma once

#include <cstdint>

#include "modules/executor/posture_units.hpp"

namespace robuter::executor {

// Tolerances and speed limits of the go-to controller.
struct GoToSettings {
  std::int32_t position_tolerance = 200;  // arrived within this distance of (x, y), 0.1 mm (2 cm)
  std::int32_t angle_tolerance = 200;     // facing within this of the bearing / theta, 0.01° (2°)
  std::int32_t reorient_angle = 2'000;    // heading error that stops driving to turn again, 0.01° (20°)
  std::int32_t max_drive_cm_s = 20;       // fastest wheel while driving, cm/s
  std::int32_t max_turn_cm_s = 10;        // fastest wheel while turning on the spot, cm/s
  std::int32_t min_cm_s = 1;              // slowest non-zero wheel speed, cm/s
  double drive_gain = 1.0;                // forward speed per distance left, 1/s
  double turn_gain = 1.5;                 // turning rate per heading error, 1/s
  std::uint32_t wheel_base_mm = 600;      // DBW, mm
};

enum class GoToPhase : std::uint8_t { idle, turn_to_target, drive, turn_to_heading, done };

// Wheel speeds asked by the controller, cm/s.
struct WheelSpeeds {
  std::int32_t left = 0;   // cm/s
  std::int32_t right = 0;  // cm/s
};

class GoToController {
 public:
  explicit GoToController(const GoToSettings& s = {}) : s_(s) {}
  // Starts towards `target` (0.1 mm, 0.01°).
  void start(const PostureUnits& target);
  // Stops controlling (no speeds asked any more).
  void cancel() { phase_ = GoToPhase::idle; }
  // One control step from the current posture: the wheel speeds to ask for; zero once done.
  WheelSpeeds step(const PostureUnits& now);
  bool active() const { return phase_ != GoToPhase::idle && phase_ != GoToPhase::done; }
  GoToPhase phase() const { return phase_; }
  const PostureUnits& target() const { return target_; }
  const GoToSettings& settings() const { return s_; }

 private:
  // Speeds that turn on the spot to reduce `error_rad` (positive: counter-clockwise).
  WheelSpeeds turn(double error_rad) const;

  GoToSettings s_;
  GoToPhase phase_ = GoToPhase::idle;
  PostureUnits target_{};
};

}  // namespace robuter::executor

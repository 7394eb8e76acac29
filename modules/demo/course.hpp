// SPDX-License-Identifier: GPL-3.0-or-later
// The seed's demonstration course (dem.c, annex A) as a pure state machine: a loop driven on
// odometry, re-calibrated once a lap against known boxes in three phases.
#pragma once

#include <array>
#include <cstdint>

#include "modules/demo/demo_params.hpp"
#include "modules/topics.hpp"

namespace robuter::demo {

// The course and the calibration, mm and cm/s (seed dem.h: DISTX 1.2 m, DISTY 1 m, RAIO 1 m).
struct CourseSettings {
  double distx_mm = 1200.0;         // front sensor to the front box when calibrated in x (DISTX)
  double disty_mm = 1000.0;         // side sensors to the calibration boxes when on the lane (DISTY)
  double raio_mm = 1000.0;          // radius of both half-circles without error (RAIO)
  double straight_mm = 2500.0;      // the straight leg after the recalibration point
  double lane_mm = 2100.0;          // the lane driven back before calibrating (ends short of the calibration x)
  std::int32_t speed_cm_s = 20;     // cruising wheel speed (seed 20)
  std::int32_t slow_cm_s = 10;      // approach speed (seed 10)
  std::int32_t align_cm_s = 1;      // the wheel that turns while aligning (seed 1)
  int sensor_a = 17;                // the side sensors that must read alike (seed text: 17 and 19)
  int sensor_b = 19;
  int front_sensor = 1;             // the sensor that measures DISTX
  double align_tolerance_mm = 5.0;  // readings this close count as alike
  int calibration_readings = 3;     // medians of this many fresh readings (1..kMaxCalibrationReadings; 1: the seed's one)
  std::uint32_t laps = 6;           // laps, then stop (seed: n > 5 ends the program); 0 = for ever
  std::uint32_t wheel_base_mm = 600;  // DBW
  std::uint64_t stale_ticks = 100;  // a ring reading older than this is not used, ticks
  std::uint64_t calibration_timeout_ticks = 6000;  // align + advance longer than this: failed (boxes not found), ticks (0: no limit)
};

// What the course is doing: the vocabulary's DemoPhase (protocol/codec/vocabulary.hpp), which XD prints.
using Phase = DemoPhase;

struct CourseInputs {
  std::uint64_t tick = 0;                     // now
  SectorPose pose{};                          // odometry now (0.1 mm, 0.01°)
  const UltrasonicRanges* ranges = nullptr;   // the ring (never null in use)
  bool emergency = false;                     // an emergency holds: wait (the seed's emergency module stops it)
};

struct CourseOutput {
  std::int32_t left = 0;    // cm/s
  std::int32_t right = 0;   // cm/s
  bool request = false;     // publish
  Phase phase = Phase::wait;
  std::uint32_t lap = 0;    // laps completed
  bool lap_ended = false;   // this step ended a lap (the recalibration point)
};

class Course {
 public:
  explicit Course(const CourseSettings& s) : s_(s) {}
  void start() { phase_ = Phase::wait; lap_ = 0; }
  void stop() { phase_ = Phase::done; }
  CourseOutput step(const CourseInputs& in);
  Phase phase() const { return phase_; }
  const CourseSettings& settings() const { return s_; }
  std::uint32_t lap() const { return lap_; }
  // The last calibration: side reading (ERRO) and the half-circle radius it gave, mm.
  double last_side_mm() const { return side_mm_; }
  double last_radius_mm() const { return radius_mm_; }

 private:
  // Where the robot is in the course frame (origin the recalibration point, x along the first leg), mm / rad.
  struct Local {
    double x = 0.0, y = 0.0, th = 0.0;
  };
  Local local(const SectorPose& p) const;
  // Wheel speeds that follow the line through (x0, y0) along heading h, mm / rad.
  CourseOutput follow_line(double x0, double y0, double h, const Local& at, std::int32_t speed) const;
  // Wheel speeds that follow the circle of centre (cx, cy), radius r, clockwise (right turns).
  CourseOutput follow_arc(double cx, double cy, double r, const Local& at, std::int32_t speed) const;
  // A fresh echo of ring sensor `s` (1..24), mm, or < 0 (none, stale, or no echo: nothing within
  // the firing's reach says where a box is not, not where it is).
  double reading(const CourseInputs& in, int s) const;
  CourseOutput out(std::int32_t l, std::int32_t r) const;

  // The last few fresh readings of one sensor, each less an offset (the front box's: the path
  // driven when it was taken, so all of them say where the box is), mm.
  struct Recent {
    std::array<double, kMaxCalibrationReadings> mm{};  // ring of values
    int count = 0;                                       // values held (≤ the setting)
    int next = 0;                                        // slot the next one goes to
    std::uint64_t tick = 0;                              // read tick of the last one taken
  };
  // Takes sensor s's reading into r when it is fresh and new, plus `offset`.
  void take(const CourseInputs& in, int s, Recent& r, double offset = 0.0) const;
  // The median of r's values once it holds calibration_readings of them, else < 0.
  double median(const Recent& r) const;

  CourseSettings s_;
  Phase phase_ = Phase::done;
  std::uint32_t lap_ = 0;
  SectorPose origin_{};                 // odometry at the recalibration point
  double turn_start_th_ = 0.0;          // heading when the current arc began, rad (course frame)
  double arc_cx_ = 0.0, arc_cy_ = 0.0, arc_r_ = 0.0;  // current arc, mm
  double side_mm_ = 0.0, radius_mm_ = 0.0;
  Recent side_a_, side_b_;              // the side sensors' last readings while aligning, mm
  Recent front_;                        // the front box's distance from where the advance began, mm
  double advance_x_ = 0.0, advance_y_ = 0.0;  // where the advance began (course frame), mm
  std::uint64_t calibration_tick_ = 0;  // tick the calibration (align) began
  int align_dir_ = 0;                   // +1 turning right, −1 left, 0 not decided
};

}  // namespace robuter::demo

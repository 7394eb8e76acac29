// SPDX-License-Identifier: GPL-3.0-or-later
// The demonstration's course state machine alone: a unicycle driven by its wheel speeds, ring
// readings from the calibration boxes' two face lines, one noise pulse injected where it hurts —
// the calibration's medians ignore it (issue #19).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "modules/demo/course.hpp"
#include "robot/robot_model.hpp"

namespace robuter::demo {
namespace {

constexpr double kPi = std::numbers::pi;

// Where the course ends its advance, and how far the robot's front then is from the front box.
struct AdvanceEnd {
  bool reached = false;     // the course began its calibration circle
  double front_gap_mm = 0;  // front face to the front box's face then, mm (DISTX when right)
};

// Drives the course from its start to the calibration circle, in the course's frame (origin the
// recalibration point, the first leg along +x): the lane comes back at y = −2 RAIO heading −x,
// the side boxes' face runs along y = −2 RAIO − 350 − DISTY (on the robot's left there), the front
// box's face stands across x = −695 − DISTX (DISTX ahead of the front when the axle is at x = 0,
// where the circle back to the origin begins). Every sensor is read every `period` ticks (its
// perpendicular distance to the face its beam meets within 12.5°; none otherwise). With `pulse`,
// the advance's first front reading is a noise pulse of 300 mm instead.
AdvanceEnd drive_to_the_circle(int readings, bool pulse) {
  CourseSettings s;
  s.calibration_readings = readings;
  Course course(s);
  course.start();
  const double side_face = -2.0 * s.raio_mm - 350.0 - s.disty_mm;
  const double front_face = -695.0 - s.distx_mm;
  double x = 0.0, y = 0.0, th = 0.0;  // the robot's true pose, mm and rad
  UltrasonicRanges ranges;
  const int period = 30;
  bool pulsed = false;
  for (std::uint64_t tick = 1; tick < 200000; ++tick) {
    if (tick % period == 0) {
      ++ranges.scans;
      for (const int sn : {s.sensor_a, s.sensor_b, s.front_sensor}) {
        const auto& m = robot::kRobuter.ring.sensor(sn).mount;
        const double px = x + 1000.0 * (m.x * std::cos(th) - m.y * std::sin(th));
        const double py = y + 1000.0 * (m.x * std::sin(th) + m.y * std::cos(th));
        const double d = th + m.direction;
        double r = 0.0;
        if (std::sin(d) < -std::cos(12.5 * kPi / 180.0)) r = py - side_face;   // the side boxes' face (normal +y)
        if (std::cos(d) < -std::cos(12.5 * kPi / 180.0)) r = px - front_face;  // the front box's face (normal +x)
        if (sn == s.front_sensor && pulse && !pulsed && course.phase() == Phase::advance) {
          r = 300.0;  // a noise pulse: a short reading where the box is not
          pulsed = true;
        }
        const auto i = static_cast<std::size_t>(sn - 1);
        ranges.mm[i] = static_cast<std::uint16_t>(std::lround(std::clamp(r, 0.0, 4950.0)));
        ranges.read_tick[i] = tick;
        ranges.no_echo = r > 0.0 ? ranges.no_echo & ~(1u << i) : ranges.no_echo | (1u << i);
      }
    }
    CourseInputs in;
    in.tick = tick;
    in.pose = {static_cast<std::int32_t>(std::lround(x * 10.0)), static_cast<std::int32_t>(std::lround(y * 10.0)),
               static_cast<std::int32_t>(std::lround(th * 180.0 / kPi * 100.0))};
    in.ranges = &ranges;
    const CourseOutput o = course.step(in);
    if (o.phase == Phase::circle) {
      const double front_x = x + 695.0 * std::cos(th);
      return {true, front_x - front_face};
    }
    if (o.phase == Phase::failed) return {};
    // 10 ms of a unicycle at the commanded wheel speeds (cm/s).
    const double v = 5.0 * (o.left + o.right), w = 10.0 * (o.right - o.left) / s.wheel_base_mm;
    x += 0.01 * v * std::cos(th);
    y += 0.01 * v * std::sin(th);
    th = std::remainder(th + 0.01 * w, 2.0 * kPi);
  }
  return {};
}

TEST(DemoCourse, TheAdvanceStopsAtDistxFromTheFrontBox) {
  for (const int readings : {1, 3}) {
    const AdvanceEnd e = drive_to_the_circle(readings, false);
    ASSERT_TRUE(e.reached) << readings;
    EXPECT_NEAR(e.front_gap_mm, 1200.0, 25.0) << readings;
  }
}

// One noise pulse as the advance's first front reading: the seed's single reading takes it for
// the box and begins the circle at once, 400 mm short; the median of three ignores it.
TEST(DemoCourse, ANoisePulseAtTheFrontBoxIsNotTheCalibration) {
  const AdvanceEnd single = drive_to_the_circle(1, true);
  ASSERT_TRUE(single.reached);
  EXPECT_GT(single.front_gap_mm, 1500.0);
  const AdvanceEnd median = drive_to_the_circle(3, true);
  ASSERT_TRUE(median.reached);
  EXPECT_NEAR(median.front_gap_mm, 1200.0, 25.0);
  std::printf("advance ended %.0f mm from the front box with one reading, %.0f mm with the median of three\n",
              single.front_gap_mm, median.front_gap_mm);
}

}  // namespace
}  // namespace robuter::demo

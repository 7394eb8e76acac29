// SPDX-License-Identifier: GPL-3.0-or-later
// The course: legs followed on odometry, the three-phase calibration against the boxes.
#include "modules/demo/course.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "robot/angles.hpp"

namespace robuter::demo {

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kHeadingGain = 1.0;     // turn rate per heading error, 1/s
constexpr double kLateralGain = 0.004;   // turn rate per mm off the path, rad/s per mm
constexpr double kMaxLateralTerm = 0.3;  // cap of the lateral correction, rad/s
constexpr double kEndTolerance = 0.003;  // a half-circle ends this close to 180°, rad
using robot::wrap_angle;  // (−π, π]: robot/angles.hpp
}  // namespace

Course::Local Course::local(const SectorPose& p) const {
  const double th0 = origin_.theta * 0.01 * kPi / 180.0;
  const double dx = (p.x - origin_.x) * 0.1, dy = (p.y - origin_.y) * 0.1;
  return {dx * std::cos(th0) + dy * std::sin(th0), -dx * std::sin(th0) + dy * std::cos(th0),
          wrap_angle(p.theta * 0.01 * kPi / 180.0 - th0)};
}

CourseOutput Course::out(std::int32_t l, std::int32_t r) const {
  CourseOutput o;
  o.left = l;
  o.right = r;
  o.request = phase_ != Phase::done && phase_ != Phase::failed;
  o.phase = phase_;
  o.lap = lap_;
  return o;
}

// Why closed loop: the seed set fixed wheel ratios (its one visible arc, a left quarter circle of
// 1 m at 20 : 10.77, docs/DOORS.md DM-1), whose whole cm/s leave a 1 m circle 3 % off (20 and
// 11 cm/s turn on 1.03 m); following the path on odometry removes that error.
CourseOutput Course::follow_line(double x0, double y0, double h, const Local& at, std::int32_t speed) const {
  const double left_of = -(at.x - x0) * std::sin(h) + (at.y - y0) * std::cos(h);  // mm
  const double w = kHeadingGain * wrap_angle(h - at.th) - std::clamp(kLateralGain * left_of, -kMaxLateralTerm, kMaxLateralTerm);
  const double half = s_.wheel_base_mm / 20.0;  // half the wheel base, cm
  return out(static_cast<std::int32_t>(std::lround(speed - w * half)), static_cast<std::int32_t>(std::lround(speed + w * half)));
}

CourseOutput Course::follow_arc(double cx, double cy, double r, const Local& at, std::int32_t speed) const {
  const double phi = std::atan2(at.y - cy, at.x - cx);
  const double tangent = phi - kPi / 2.0;                              // clockwise travel
  const double outside = std::hypot(at.x - cx, at.y - cy) - r;         // mm: left of a clockwise path
  const double v = speed * 10.0;                                       // mm/s
  const double w = -v / r + kHeadingGain * wrap_angle(tangent - at.th) -
                   std::clamp(kLateralGain * outside, -kMaxLateralTerm, kMaxLateralTerm);
  const double half = s_.wheel_base_mm / 20.0;
  return out(static_cast<std::int32_t>(std::lround(speed - w * half)), static_cast<std::int32_t>(std::lround(speed + w * half)));
}

double Course::reading(const CourseInputs& in, int s) const {
  const auto i = static_cast<std::size_t>(s - 1);
  const std::uint64_t t = in.ranges->read_tick[i];
  if (in.ranges->mm[i] == 0 || t == 0 || in.tick - t > s_.stale_ticks) return -1.0;
  if ((in.ranges->no_echo >> i) & 1u) return -1.0;
  return in.ranges->mm[i];
}

void Course::take(const CourseInputs& in, int s, Recent& r, double offset) const {
  const double v = reading(in, s);
  const std::uint64_t t = in.ranges->read_tick[static_cast<std::size_t>(s - 1)];
  if (v < 0.0 || t == r.tick) return;
  r.tick = t;
  const int n = std::clamp(s_.calibration_readings, 1, kMaxCalibrationReadings);
  r.mm[static_cast<std::size_t>(r.next)] = v + offset;
  r.next = (r.next + 1) % n;
  r.count = std::min(r.count + 1, n);
}

// Why a median: one noise pulse (a short reading where the box is not) or one cross-talk echo
// would otherwise be the calibration (docs/DOORS.md §4); the median of three ignores one.
double Course::median(const Recent& r) const {
  const int n = std::clamp(s_.calibration_readings, 1, kMaxCalibrationReadings);
  if (r.count < n) return -1.0;
  std::array<double, kMaxCalibrationReadings> v = r.mm;
  const auto mid = v.begin() + n / 2;
  std::nth_element(v.begin(), mid, v.begin() + n);
  return *mid;
}

CourseOutput Course::step(const CourseInputs& in) {
  if (phase_ == Phase::done || phase_ == Phase::failed) return out(0, 0);
  if (phase_ == Phase::wait) {
    if (in.ranges->scans == 0) return out(0, 0);
    origin_ = in.pose;  // the robot starts on the recalibration point (seed: odometry set there)
    phase_ = Phase::out;
  }
  if (in.emergency) return out(0, 0);  // stopped by the emergency module; carry on once it clears
  // Why a limit: without the boxes the seed would turn on one wheel for ever; a demonstration
  // that cannot calibrate stops and says so.
  if ((phase_ == Phase::align || phase_ == Phase::advance) && s_.calibration_timeout_ticks > 0 &&
      in.tick - calibration_tick_ > s_.calibration_timeout_ticks) {
    phase_ = Phase::failed;
    return out(0, 0);
  }
  const Local at = local(in.pose);
  const double R = s_.raio_mm;
  switch (phase_) {
    case Phase::out:
      if (at.x < s_.straight_mm) return follow_line(0.0, 0.0, 0.0, at, s_.speed_cm_s);
      phase_ = Phase::turn;
      turn_start_th_ = at.th;
      [[fallthrough]];
    case Phase::turn: {
      const double turned = std::fmod(turn_start_th_ - at.th + 4.0 * kPi, 2.0 * kPi);  // clockwise, rad
      if (turned < kPi - kEndTolerance || turned > 1.5 * kPi) return follow_arc(s_.straight_mm, -R, R, at, s_.speed_cm_s);
      phase_ = Phase::lane;
      [[fallthrough]];
    }
    case Phase::lane:
      if (at.x > s_.straight_mm - s_.lane_mm) return follow_line(s_.straight_mm, -2.0 * R, kPi, at, s_.speed_cm_s);
      phase_ = Phase::align;
      align_dir_ = 0;
      calibration_tick_ = in.tick;
      side_a_ = side_b_ = Recent{};
      return out(0, 0);
    case Phase::align: {
      // Phase 1: turn on one wheel until the two side sensors read alike (seed cases 1 and 2).
      take(in, s_.sensor_a, side_a_);
      take(in, s_.sensor_b, side_b_);
      const double a = median(side_a_), b = median(side_b_);
      if (a < 0.0 || b < 0.0) return out(0, 0);
      const int want = a > b + s_.align_tolerance_mm ? 1 : (a < b - s_.align_tolerance_mm ? -1 : 0);
      if (want != 0 && (align_dir_ == 0 || want == align_dir_)) {
        align_dir_ = want;
        return want > 0 ? out(s_.align_cm_s, 0) : out(-s_.align_cm_s, 0);
      }
      side_mm_ = a;  // ERRO
      radius_mm_ = (2.0 * R + s_.disty_mm - side_mm_) / 2.0;
      phase_ = Phase::advance;
      front_ = Recent{};
      advance_x_ = at.x;
      advance_y_ = at.y;
      turn_start_th_ = at.th;  // the heading to keep
      return out(0, 0);
    }
    case Phase::advance: {
      // Phase 2: on to DISTX from the front box; each reading plus the path driven when it was
      // taken says where the box is, and between readings the median is carried by odometry.
      const double driven = std::hypot(at.x - advance_x_, at.y - advance_y_);
      take(in, s_.front_sensor, front_, driven);
      const double box = median(front_);
      if (box < 0.0) return out(0, 0);
      const double left = box - driven - s_.distx_mm;
      if (left > 0.0) {
        const auto v = static_cast<std::int32_t>(std::clamp(left / 20.0, 1.0, static_cast<double>(s_.slow_cm_s)));
        const double x0 = at.x, y0 = at.y;  // hold the aligned heading
        return follow_line(x0, y0, turn_start_th_, at, v);
      }
      // Phase 3: the half-circle to the right whose radius D = (2·RAIO + DISTY − ERRO)/2
      // brings the robot to the recalibration point whatever its y error.
      phase_ = Phase::circle;
      arc_r_ = radius_mm_;
      arc_cx_ = at.x + arc_r_ * std::sin(at.th);
      arc_cy_ = at.y - arc_r_ * std::cos(at.th);
      turn_start_th_ = at.th;
      [[fallthrough]];
    }
    case Phase::circle: {
      const double turned = std::fmod(turn_start_th_ - at.th + 4.0 * kPi, 2.0 * kPi);
      if (turned < kPi - kEndTolerance || turned > 1.5 * kPi) return follow_arc(arc_cx_, arc_cy_, arc_r_, at, s_.slow_cm_s);
      ++lap_;
      origin_ = in.pose;  // the recalibration point: a new lap starts from a known posture
      phase_ = s_.laps > 0 && lap_ >= s_.laps ? Phase::done : Phase::out;
      CourseOutput o = out(0, 0);
      o.lap_ended = true;
      return o;
    }
    default:
      return out(0, 0);
  }
}

}  // namespace robuter::demo

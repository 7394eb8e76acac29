// SPDX-License-Identifier: GPL-3.0-or-later
// Configuration (mm, counts) → planner settings (m, cells, rad).
#include "modules/planner/planner_settings.hpp"

#include <algorithm>
#include <cmath>

namespace robuter::planner {

namespace {
double mm(std::int64_t v) { return static_cast<double>(v) / 1000.0; }
}  // namespace

PlannerSettings make_settings(const PlannerModuleConfig& p, const robot::RobotModel& m, std::uint32_t pan_far_mm) {
  PlannerSettings s;
  s.map.resolution = mm(p.cell_mm);
  s.map.width = static_cast<int>(std::max<std::uint32_t>(1, p.map_width_mm / p.cell_mm));
  s.map.height = static_cast<int>(std::max<std::uint32_t>(1, p.map_height_mm / p.cell_mm));
  s.map.origin = {mm(p.map_origin_x_mm), mm(p.map_origin_y_mm)};
  s.hit_threshold = static_cast<std::uint8_t>(std::clamp<std::uint32_t>(p.hit_threshold, 1, 254));
  s.initial_count = static_cast<std::uint8_t>(std::min<std::uint32_t>(p.initial_count, s.hit_threshold - 1u));
  s.robot = m;
  const robot::Body& body = s.robot.body;

  plan::PlannerConfig& c = s.planner;
  c.footprint = p.footprint == "disc" ? plan::FootprintKind::Disc : plan::FootprintKind::Rectangle;
  c.radius = mm(p.disc_radius_mm);
  c.rectangle = plan::RectangleFootprint{body.length, body.width, body.center_ahead(), mm(p.margin_mm)};
  c.heading_slices = static_cast<int>(p.heading_slices);
  c.turn_clearance = mm(p.turn_clearance_mm);
  c.motion = plan::MotionModel::Aligned;
  c.mode = plan::SearchMode::Optimal;
  c.incremental = true;

  s.scan_passes = p.scan_passes;
  s.beam_range = mm(p.beam_range_mm);
  s.beam_half_angle = p.beam_half_angle_centideg * plan::kPi / 18000.0;
  s.pan_far = mm(pan_far_mm);
  s.follow_range = mm(p.follow_range_mm);
  s.goal_tolerance = mm(p.goal_tolerance_mm);
  const auto cap = static_cast<std::int32_t>(std::min<long>(std::lround(m.wheels.max_speed * 100.0), 100));
  s.drive_cm_s = std::min(static_cast<std::int32_t>(p.drive_speed_cm_s), cap);
  s.turn_cm_s = std::min(static_cast<std::int32_t>(p.turn_speed_cm_s), cap);
  s.wheel_base_mm = robot::mm_u(m.wheels.base);
  return s;
}

}  // namespace robuter::planner

// SPDX-License-Identifier: GPL-3.0-or-later
// The plan's layers on the plot: cells, grown obstacles, path, footprints, start and goal, with their inks.
#pragma once

#include <cairo.h>

#include <Eigen/Geometry>

#include <cmath>
#include <string>
#include <vector>

#include "modules/planner/lib/plan_snapshot.hpp"
#include "modules/planner/picture/plan_picture.hpp"
#include "picture/frame.hpp"
#include "picture/legend.hpp"
#include "picture/page.hpp"

namespace robuter::plan {

// The map frame's placement in the world (a rotation and a shift, Eigen).
class MapPlacement {
 public:
  MapPlacement(const PlanSnapshot&, const PlanPictureOptions& o)
      : rot_(Eigen::Rotation2Dd(o.map_in_world.heading).toRotationMatrix()),
        shift_(o.map_in_world.x, o.map_in_world.y), heading_(o.map_in_world.heading) {}
  // A map point (m) in the world (m).
  picture::Vec2 world(const Point2& p) const { return rot_ * picture::Vec2(p.x, p.y) + shift_; }
  // A map heading (rad) in the world (rad).
  double heading(double h) const { return h + heading_; }

 private:
  Eigen::Matrix2d rot_;   // map axes in the world
  picture::Vec2 shift_;   // map origin in the world, m
  double heading_ = 0.0;  // map x axis's heading in the world, rad
};

// Draws the plan's layers on the plot and records the inks used and the labels wished.
void draw_plan(cairo_t* cr, const PlanSnapshot& s, const picture::Frame& f, const MapPlacement& place,
               picture::Legend& legend, std::vector<picture::Label>& labels);

}  // namespace robuter::plan

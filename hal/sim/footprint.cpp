// SPDX-License-Identifier: GPL-3.0-or-later
// Rectangle-versus-edges contact: each nearby edge is moved into the robot frame and clipped.
#include "hal/sim/footprint.hpp"

#include <cmath>

namespace robuter::sim {

// Corners from the body box, rotated into the world.
void footprint_corners(const RobotGeometry& g, const Pose& pose, Vec2 out[4]) {
  const Box b = g.body();
  out[0] = to_world(pose, {b.hi.x(), b.hi.y()});
  out[1] = to_world(pose, {b.hi.x(), b.lo.y()});
  out[2] = to_world(pose, {b.lo.x(), b.lo.y()});
  out[3] = to_world(pose, {b.lo.x(), b.hi.y()});
}

// The world-frame bounding box of the rotated body selects candidate edges; each is then
// clipped exactly against the body box in the robot frame.
bool footprint_hits(const World& world, const RobotGeometry& g, const Pose& pose, double inflate,
                    GridScratch& scratch) {
  const Box body = g.body(inflate);
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  // Half extents of the rotated box around the body centre.
  const Vec2 centre_local = 0.5 * (body.lo + body.hi);
  const Vec2 half = 0.5 * (body.hi - body.lo);
  const Vec2 centre = to_world(pose, centre_local);
  const Vec2 ext(std::abs(c) * half.x() + std::abs(s) * half.y(),
                 std::abs(s) * half.x() + std::abs(c) * half.y());
  const Vec2 pad = Vec2::Constant(1e-9);
  bool hit = false;
  const auto& segs = world.segments();
  world.grid().for_each_near(centre - ext - pad, centre + ext + pad, scratch, [&](std::uint32_t i) {
    if (hit) return;
    const Segment& sg = segs[i];
    if (segment_meets_box(to_local(pose, sg.a), to_local(pose, sg.b), body)) hit = true;
  });
  return hit;
}

}  // namespace robuter::sim

// SPDX-License-Identifier: GPL-3.0-or-later
// Robot footprints as cell masks: the thesis' disc, and the Robuter's rectangle per heading slice.
#pragma once

#include <vector>

namespace robuter::plan {

// A run of mask cells on one row: offsets (dx, dy) with lo <= dx <= hi.
struct MaskRun {
  int dy;  // cells, row offset from the robot's cell
  int lo;  // cells, first column offset
  int hi;  // cells, last column offset (inclusive)
};

// The cells a robot standing at a cell's centre meets: offsets from that cell, stored as runs
// (one or more per row). An obstacle at cell o blocks the robot at p when o - p is in the mask.
struct FootprintMask {
  std::vector<MaskRun> runs;  // sorted by dy then lo

  // Why: size for tests and reports.
  int cells() const {
    int n = 0;
    for (const MaskRun& r : runs) n += r.hi - r.lo + 1;
    return n;
  }
  // Why: membership test for tests and pictures.
  bool contains(int dx, int dy) const {
    for (const MaskRun& r : runs)
      if (r.dy == dy && dx >= r.lo && dx <= r.hi) return true;
    return false;
  }
};

// The Robuter's body: a rectangle, long axis along the heading.
struct RectangleFootprint {
  double length = 1.025;        // m, along the heading
  double width = 0.700;         // m, across the heading
  double center_offset = 0.0;   // m, rectangle centre ahead of the rotation centre
  double margin = 0.0;          // m, safety margin added on every side
};

// Why: seed 000's obstacle expansion by the robot radius: cells whose square meets the disc
// of radius `radius` (m) around the centre cell, at `resolution` m per cell.
FootprintMask disc_mask(double radius, double resolution);

// Why: the rectangle swept over headings [heading_lo, heading_hi] (rad): cells meeting it at any
// heading of the interval (sampled every 0.5 degree, the rectangle grown by the largest
// displacement between samples so the union is conservative).
FootprintMask rectangle_mask(const RectangleFootprint& rect, double resolution, double heading_lo,
                             double heading_hi);

// Heading slices over the full turn: slice k of S is centred on k * 2pi / S and covers the
// headings within half a slice of it. The planner's pose is the rotation centre (the Robuter's
// axle) and the body's centre is ahead of it (center_offset), so the body is not symmetric under
// a half turn: a slice and the slice a half turn away hold different bodies.
double slice_heading(int slice, int slices);
int slice_of_heading(double heading, int slices);

// Why: seed 004's (x, y, theta) slices on a grid: one swept rectangle mask per full-turn slice,
// so a (cell, slice) free in the layers is free at every heading of the slice.
std::vector<FootprintMask> rectangle_slices(const RectangleFootprint& rect, double resolution,
                                            int slices);

// Why: half-diagonal of the rectangle about its rotation centre, the radius of the disc the
// thesis' method would need (m).
double circumscribed_radius(const RectangleFootprint& rect);
// Why: the largest disc inside the rectangle at every heading (m): the admissible relaxation.
double inscribed_radius(const RectangleFootprint& rect);

}  // namespace robuter::plan

// SPDX-License-Identifier: GPL-3.0-or-later
// The simulated world: polygonal obstacles in metres, doors, named markers, start and goal.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hal/sim/geometry.hpp"
#include "hal/sim/segment_grid.hpp"

namespace robuter::sim {

// One solid obstacle: a closed polygon (the last vertex joins the first implicitly).
struct Obstacle {
  std::string name;           // name from the file, or "obstacle N"
  std::vector<Vec2> vertices; // polygon vertices in order, m (2 vertices = a thin wall line)
  int line = 0;               // line of the source file that defined it (0 if built in code)
  Surface surface = Surface::standard;  // how its faces reflect sound
};

// An opening left in a wall, recorded so tests and the planner know where passages are.
struct Door {
  std::string name;            // name from the file
  Vec2 centre;                 // middle of the opening on the wall's centre line, m
  double width = 0.0;          // clear width of the opening, m
  double wall_direction = 0.0; // direction of the wall line, rad
  double wall_thickness = 0.0; // thickness of the wall the door is cut in, m
};

// A named pose in the world (waypoints, calibration points of a scripted mission).
struct Marker {
  std::string name;  // name from the file
  Pose pose;         // position, m, and heading, rad
};

// The world the robot moves in. Immutable once finalised, so robots and sonar models may share
// it; every query that needs scratch memory takes a GridScratch owned by the caller.
class World {
 public:
  std::string name;            // world name (file's [world] name, or the file stem)
  std::string source;          // file it was loaded from, for messages
  std::optional<Pose> start;   // robot start pose, if the file gives one
  int start_line = 0;          // line of the start pose in the source file
  std::optional<Vec2> goal;    // goal position, m, if the file gives one
  int goal_line = 0;           // line of the goal in the source file
  std::vector<Door> doors;     // openings cut in walls
  std::vector<Marker> markers; // named poses

  // Adds an obstacle; call finalize() once all are in.
  void add_obstacle(Obstacle obstacle) { obstacles_.push_back(std::move(obstacle)); }

  // Builds the edge list (each edge less its parts strictly inside another polygon: only the
  // solids' outer faces are surfaces) and the spatial grid (cells of `cell` metres).
  void finalize(double cell = 0.5);

  const std::vector<Obstacle>& obstacles() const { return obstacles_; }
  const std::vector<Segment>& segments() const { return segments_; }
  const SegmentGrid& grid() const { return grid_; }

  // Bounding box of all obstacles, m (zero box for an empty world).
  const Box& bounds() const { return bounds_; }

  // Index of the first obstacle whose polygon strictly contains p, or -1.
  int obstacle_containing(const Vec2& p) const;
  // Distance from p to the nearest surface, m; 0 inside a solid. A linear scan (tests, tools).
  double clearance(const Vec2& p) const;

 private:
  std::vector<Obstacle> obstacles_;  // solid polygons
  std::vector<Segment> segments_;    // their edges
  SegmentGrid grid_;                 // edges bucketed by cell
  Box bounds_{Vec2::Zero(), Vec2::Zero()};  // bounding box of the edges, m
};

}  // namespace robuter::sim

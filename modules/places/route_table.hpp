// SPDX-License-Identifier: GPL-3.0-or-later
// Every place-to-place route as the points the planner drives through, computed once at start-up.
#pragma once

#include <cstddef>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "modules/places/place_graph.hpp"

namespace robuter::places {

// A point a route passes through, in the place graph's frame.
struct ViaPoint {
  std::int32_t x = 0;        // 0.1 mm
  std::int32_t y = 0;        // 0.1 mm
  std::int32_t theta = 0;    // 0.01 degree, (-18000, 18000]: the heading to turn to there, when has_theta
  bool has_theta = false;    // the point before a narrow door: face the door (drive through forwards)
  bool spin = false;         // exploration: a place's centre, where the robot turns a full circle and scans
};

// How a route is turned into points (docs/PLACES.md, "Going to a place").
struct ViaRules {
  double before = 1.1;      // m: a narrow door's first point, this far before it along the door's
                            // normal: room to turn in place to face it (the body's turning
                            // circle, 0.62 m, and the 0.25 m turn clearance, from the wall)
  double after = 0.9;       // m: its second point, this far beyond it (the body, 0.33 m behind
                            // the axle, clear of the opening)
  double wide_door = 1.5;   // m: a door at least this wide is passed through one point, its middle
  double long_leg = 12.5;   // m: two points of a route further apart than this across one place
                            // get its centre between them (the planner's 16 m window holds a
                            // leg of up to 14.3 m along each axis; corridor pieces are <= 12.1 m)
};

// The routes between every two places of a graph: for each (from, to) whether one exists, the
// doors it crosses, and its points: per narrow door one point before and one after it, per wide
// door its middle, a place's centre between two points of it more than ViaRules::long_leg
// apart, then the goal place's centre. Built (and allocated) once; lookups only read.
class RouteTable {
 public:
  static constexpr std::size_t kMaxPoints = 64;  // points of one route the planner's goal holds

  RouteTable() = default;
  RouteTable(const PlaceGraph& graph, const ViaRules& rules = {});

  std::size_t places() const { return n_; }
  // Why: false when no chain of doors joins them, or the route needs more than kMaxPoints points.
  bool found(std::size_t from, std::size_t to) const { return entry(from, to).found; }
  // Why: the route's points, the goal's centre last (from == to: the centre alone).
  std::span<const ViaPoint> points(std::size_t from, std::size_t to) const;
  // Why: seed 003's exploration of the same route (XQ <n> 1): the start place's centre, each
  // door's points and the entered place's centre in turn, each centre a `spin` point (a full
  // turn and a scan there), then the goal place's centre again, as the goal. Written into `out`
  // (no allocation); returns the count, or 0 when not found or more than out.size().
  std::size_t explore_points(std::size_t from, std::size_t to, std::span<ViaPoint> out) const;
  // Why: the doors the route crosses, and the route's length (m, centre to centre through the doors).
  std::size_t doors(std::size_t from, std::size_t to) const { return entry(from, to).doors; }
  double length(std::size_t from, std::size_t to) const { return entry(from, to).length; }

 private:
  struct Entry {
    bool found = false;      // a route exists and fits kMaxPoints
    std::size_t first = 0;   // index of its first point in points_
    std::size_t count = 0;   // points
    std::size_t doors = 0;   // doors crossed
    double length = 0.0;     // m
    std::size_t legs_first = 0;  // index of its first leg in legs_ (doors legs follow)
  };
  struct LegRef {
    std::uint32_t pass = 0;   // the door crossed, the way it is crossed: index into passes_
    std::uint32_t place = 0;  // the place entered through it
  };
  struct Pass {
    std::array<ViaPoint, 2> pts{};  // a door's points when entering one of its places
    std::size_t count = 0;          // 1 (a wide door's middle) or 2 (before and after a narrow one)
  };
  const Entry& entry(std::size_t from, std::size_t to) const { return entries_[from * n_ + to]; }
  // The one rule for a route's points: each leg's pass (and, exploring, each centre), the goal last.
  std::size_t write(std::size_t from, std::size_t to, bool explore, std::span<ViaPoint> out) const;

  std::size_t n_ = 0;              // places
  double long_leg_ = 0.0;          // m, ViaRules::long_leg
  std::vector<Entry> entries_;     // n_ x n_, row = from
  std::vector<ViaPoint> points_;   // every route's points, one after the other
  std::vector<LegRef> legs_;       // every route's legs, one after the other (Entry::legs_first)
  std::vector<Pass> passes_;       // 2 per door: entering door.a, entering door.b
  std::vector<ViaPoint> centres_;  // per place
};

// Why: the unit normal at a door of `place`'s boundary, pointing into the place (from the edge
// nearest the door's middle; the polygon is counter-clockwise, so inwards is to the left).
Vec2 door_normal_into(const Place& place, const Door& door);

}  // namespace robuter::places

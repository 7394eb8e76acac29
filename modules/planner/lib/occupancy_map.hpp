// SPDX-License-Identifier: GPL-3.0-or-later
// The occupancy grid: hit/miss counts per cell (seed 003), free / occupied / unknown, change log.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "modules/planner/lib/geometry.hpp"

namespace robuter::plan {

// What a cell is known to be.
enum class CellState : std::uint8_t { Free, Occupied, Unknown };

// Size and placement of a grid in the world.
struct MapGeometry {
  int width = 300;           // cells along x (the thesis: 15 m at 5 cm)
  int height = 300;          // cells along y
  double resolution = 0.05;  // m per cell side
  Point2 origin{};           // m, world position of the lower-left corner of cell (0, 0)
};

// A grid of hit counts. Never seen = unknown; a beam's first touch starts a cell at `initial`
// (0 by default; seed 003 starts every cell at 5), then a hit adds 1, a miss takes 1 down to 0;
// count >= threshold = occupied, otherwise free. Cells whose state changes are logged once
// until the log is cleared, so layers built on the map can update incrementally.
class OccupancyMap {
 public:
  static constexpr std::uint8_t kUnknown = 255;   // count value of a never-seen cell
  static constexpr std::uint8_t kMaxCount = 254;  // hits saturate here
  static constexpr std::uint8_t kDefaultThreshold = 10;

  explicit OccupancyMap(const MapGeometry& geometry = {},
                        std::uint8_t threshold = kDefaultThreshold, std::uint8_t initial = 0);

  const MapGeometry& geometry() const { return geo_; }
  int width() const { return geo_.width; }
  int height() const { return geo_.height; }
  double resolution() const { return geo_.resolution; }
  std::uint8_t threshold() const { return threshold_; }
  std::uint8_t initial_count() const { return initial_; }
  std::size_t cell_count() const { return counts_.size(); }

  bool contains(Cell c) const {
    return c.x >= 0 && c.y >= 0 && c.x < geo_.width && c.y < geo_.height;
  }
  std::uint32_t index(Cell c) const {
    return static_cast<std::uint32_t>(c.y) * static_cast<std::uint32_t>(geo_.width) +
           static_cast<std::uint32_t>(c.x);
  }
  Cell cell_of_index(std::uint32_t i) const {
    const auto w = static_cast<std::uint32_t>(geo_.width);
    return {static_cast<int>(i % w), static_cast<int>(i / w)};
  }
  // Cell containing a world point (may lie outside the map: check contains()).
  Cell cell_of(Point2 p) const;
  // World position of a cell's centre.
  Point2 center(Cell c) const;

  std::uint8_t count(Cell c) const { return counts_[index(c)]; }
  CellState state(Cell c) const { return state_of(counts_[index(c)]); }
  CellState state_at(std::uint32_t i) const { return state_of(counts_[i]); }
  CellState state_of(std::uint8_t n) const {
    if (n == kUnknown) return CellState::Unknown;
    return n >= threshold_ ? CellState::Occupied : CellState::Free;
  }

  // Raw write of a count (kUnknown to forget the cell); logs a state change.
  void set_count(Cell c, std::uint8_t n);
  // A known obstacle (environment file, saved map): count raised to the threshold.
  void mark_occupied(Cell c);
  // A known free cell: count 0.
  void mark_free(Cell c);
  // Every cell back to unknown (logs the changes).
  void clear();
  // Why: the planner's window moves by whole cells (docs/PLANNER.md, "The window"): the origin
  // moves by (dx, dy) cells, each count stays with its place in the world, the cells that come
  // into view are unknown. In place (no allocation); the change log is cleared, since whatever
  // was built on the map is rebuilt.
  void shift(int dx, int dy);

  // One range reading: cells from the origin's cell up to the end of the beam lose 1 (down to
  // 0, and become seen); if range < max_range the last cell is a hit and gains 1. A never-seen
  // cell counts from `initial_count()`. Angles in rad,
  // lengths in m; the beam is clipped to the map.
  void integrate_beam(Point2 origin, double angle, double range, double max_range);

  // Indexes of cells whose state changed since the last clear_changes(), each once.
  std::span<const std::uint32_t> changes() const { return changes_; }
  void clear_changes();

 private:
  void write(std::uint32_t i, std::uint8_t n);

  MapGeometry geo_;
  std::uint8_t threshold_;                 // hits for an obstacle
  std::uint8_t initial_;                   // count a never-seen cell starts from when a beam touches it
  std::vector<std::uint8_t> counts_;       // per cell: hits, or kUnknown
  std::vector<std::uint8_t> logged_;       // per cell: 1 when already in changes_
  std::vector<std::uint32_t> changes_;     // cell indexes, reserved to the cell count
};

// Why: Liang-Barsky clip of the segment p-q to the map grown by one cell, so that lines far
// outside cost nothing; a segment inside is returned unchanged. False if it misses the map.
bool clip_segment_to_map(const MapGeometry& geometry, Point2& p, Point2& q);

}  // namespace robuter::plan

// SPDX-License-Identifier: GPL-3.0-or-later
// Obstacle evidence and free-space certificates of the ring, in a rolling grid of the odometry frame.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace robuter::emergency {

// What the grid knows about one point at a given tick.
enum class CellState : std::uint8_t {
  unknown,   // never certified free, and no obstacle evidence
  obstacle,  // obstacle evidence newer than (or as new as) the last free certificate
  stale,     // certified free, but longer ago than the age limit
  free,      // certified free within the age limit
};

// Static structure the robot knows for sure — the planner's a-priori map ([planner] map_file) or
// the place graph's walls — seen from the odometry frame: where an echo is explained. Implemented
// by the firmware's glue, which places the map in the odometry frame (the localisation's
// correction, docs/LOCALISATION.md: the odometry drifts from the map, the structure must not).
class KnownStructure {
 public:
  virtual ~KnownStructure() = default;
  // Called at the start of each activation that places readings: where the map lies in the
  // odometry frame now. Bounded work, no allocation.
  virtual void update() {}
  // Whether the point p (odometry frame, m) lies on known structure (within the map's tolerance).
  virtual bool occupied(const Eigen::Vector2d& p) const = 0;
};

// A recent reading with an echo, as narrowing sees it: its cone saw through to `range`.
struct SeenCone {
  std::uint64_t tick = 0;                             // its read tick, 0 = none
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  // the transducer, odometry frame, m
  double direction = 0.0;                             // the cone's axis, rad
  double range = 0.0;                                 // its echo, m
};

// Shape and behaviour of the grid.
struct GridSettings {
  double cell = 0.025;              // cell side, m
  int side = 256;                   // cells per side of the window (a power of two), count
  double blanking = 0.15;           // a reading certifies nothing nearer to its transducer, m
  double half_angle = 0.218166;     // beam cone half-angle, rad (12.5°)
  double reach = 2.5;               // a reading certifies free space and marks echoes this far at most, m
  double shrink = 0.03;             // free space ends this much short of an echo (range noise), m
  int recentre_cells = 24;          // the window follows once the robot is this many cells off its centre
  // Narrowing (mark_arc, docs/SAFETY.md §13): an echo whose arc meets known structure (the
  // a-priori map) is explained by it; its arc then loses the points a cone at most `narrow_age`
  // ticks old saw through along a line of sight within `narrow_sight` of the echo's. Without
  // known structure on the arc, or narrow_age 0, the whole arc is marked.
  std::uint64_t narrow_age = 0;     // ticks
  double narrow_sight = 0.3491;     // rad (20°)
  // Evidence of one echo that no later echo marked again counts this long (0: for ever): a
  // spurious echo's arc, left where no cone looks again (docs/SAFETY.md §13, "Unconfirmed").
  std::uint64_t single_age = 0;     // ticks
  // An echo from farther away clears obstacle evidence at most `sight_age` ticks old only looking
  // along nearly the line of sight the evidence was seen along (within contradict_sight), with
  // the cell at least as far inside its cone from either edge (docs/SAFETY.md §13, "Multipath"):
  // a surface too oblique to echo to one transducer reflects its beam on (a long reading) while
  // another transducer, less oblique, marks it. Both within the same angle, and no cone can glance
  // off the straight face that echoed along the evidence's line: half the cone's half-angle each.
  // Older evidence (no echo repeated it) any farther echo clears (sight_age 1: all of it, the
  // rule before this one, as tests/safety_sim/multipath_census.hpp measures it).
  double contradict_sight = 0.1091; // rad (6.25°)
  std::uint64_t sight_age = 0;      // ticks (0: evidence of any age is kept so)
};

// A rolling window of cells centred on the robot (toroidal storage: moving the window clears only
// the rows and columns that leave it). Per cell: the tick of its last free certificate and of its
// newest obstacle evidence. Allocated once at construction; no other call allocates.
class EvidenceGrid {
 public:
  explicit EvidenceGrid(const GridSettings& s);

  // Forgets everything (a fresh start). Work: side² cells.
  void reset();
  // The odometry frame was set (AC): the obstacle evidence is carried into the new frame, where
  // x_new = rotation · x_old + translation, and the window re-placed around `robot` (new frame, m);
  // free certificates are forgotten (space is certified again by the next readings). A cell of
  // evidence marks every new cell of its turned square's bounding box: the carried evidence is
  // never narrower than it was. Evidence carried before is carried again from where it was
  // observed (its exact centre and the turn since), not from the cells it marked, so frame after
  // frame at rest never widens it. At most kCarried cells, nearest to the robot first (within 1 m,
  // then the rest). Work: 2 × side² cells + 9 × kCarried box checks and marks.
  void carry(const Eigen::Matrix2d& rotation, const Eigen::Vector2d& translation, const Eigen::Vector2d& robot);
  static constexpr std::size_t kCarried = 8192;  // cells of evidence carried through a new frame, count
  // Keeps the window around `robot` (odometry frame, m). Work: at most side² cells when it jumps
  // by a whole window, else (columns + rows moved) × side.
  void follow(const Eigen::Vector2d& robot);
  // One ring reading at `tick`, fired from `origin` along `direction` (odometry frame, m, rad),
  // `range` m. The cone is certified free from the blanking range to range − shrink (cells wholly
  // in that band, centre in the cone); the echo's arc is marked as obstacle evidence unless
  // `no_echo`. `contradicts` false: the certificate leaves cells with obstacle evidence as they
  // are (a single no-echo may be a lost echo); true: it clears evidence seen along nearly its own
  // line of sight (within contradict_sight), never evidence seen from elsewhere. Work: the cells of the cone's bounding box (≤ 4,500
  // at the default reach) plus ≤ 200 arc samples.
  void add_reading(std::uint64_t tick, const Eigen::Vector2d& origin, double direction, double range, bool no_echo,
                   bool contradicts);
  // The two halves of add_reading, for a batch of readings taken together (every cone, then every
  // arc). mark_arc narrows the arc by `seen`, recent cones with an echo (docs/SAFETY.md §13); what
  // is left of an explained arc off the known structure is *soft* evidence, which a later
  // certificate along nearly the same line of sight (within narrow_sight) clears even without an
  // echo. certify_cone never clears hard evidence unless `contradicts`, and then only along
  // nearly the line of sight it was seen along.
  void certify_cone(std::uint64_t tick, const Eigen::Vector2d& origin, double direction, double range, bool no_echo,
                    bool contradicts);
  void mark_arc(std::uint64_t tick, const Eigen::Vector2d& origin, double direction, double range, bool no_echo,
                std::span<const SeenCone> seen = {});
  // Whether cone c, at most narrow_age old at `tick`, saw through p (inside it, between the
  // blanking range and its echo less the range noise) along a line of sight within narrow_sight
  // of the one from `from` to p.
  bool sees_through(const SeenCone& c, const Eigen::Vector2d& p, const Eigen::Vector2d& from, std::uint64_t tick) const;
  // Changes how long a cone narrows an arc (the kernel's tick is known at init), ticks.
  void set_narrow_age(std::uint64_t ticks) { s_.narrow_age = ticks; }
  void set_single_age(std::uint64_t ticks) { s_.single_age = ticks; }
  void set_sight_age(std::uint64_t ticks) { s_.sight_age = ticks; }
  // The structure that explains echoes (nullptr: none, no narrowing); it must outlive the grid.
  void set_known_structure(KnownStructure* known) { known_ = known; }
  // Where the known structure lies now (KnownStructure::update), once per activation.
  void update_structure() {
    if (known_ != nullptr) known_->update();
  }
  // Arc cells narrowing left unmarked / echoes whose every point was ruled out (marked whole), counts.
  std::uint64_t narrowed_cells() const { return narrowed_cells_; }
  std::uint64_t unexplained_echoes() const { return unexplained_echoes_; }
  static constexpr std::size_t kMaxSeen = 64;  // cones one arc is tested against, at most
  static constexpr int kArcCells = 256;        // cells one arc crosses, at most (≤ 90 samples at the 2.5 m reach)
  // Certifies free every cell wholly under the rectangle [lo, hi] (robot frame, m) of a robot at
  // (position, heading): the body is there, so nothing else is. Work: cells of its bounding box.
  void certify_rectangle(std::uint64_t tick, const Eigen::Vector2d& position, double heading,
                         const Eigen::Vector2d& lo, const Eigen::Vector2d& hi);
  // What the grid says of the point p (odometry frame, m) at `tick`; free certificates older than
  // `max_age` ticks are stale. Outside the window: unknown.
  CellState state(const Eigen::Vector2d& p, std::uint64_t tick, std::uint64_t max_age) const;
  // The tick of the newest obstacle evidence at p (0: none, or outside the window).
  std::uint64_t evidence_tick(const Eigen::Vector2d& p) const;

  const GridSettings& settings() const { return s_; }
  // Global cell index of the window's low corner (tests).
  Eigen::Vector2i window_origin() const { return {ox_, oy_}; }

 private:
  // A cell's two ticks; 0 = never.
  struct Cell {
    std::uint64_t free_tick = 0;  // last free certificate, ticks
    std::uint64_t hit_tick = 0;   // newest obstacle evidence, ticks
  };
  // A direction (rad) in 256 steps of a turn (the line of sight a soft cell was seen along).
  static std::uint8_t sight_code(double angle);
  // Whether the line of sight (dx, dy) to slot sl's cell lies within `within` (rad) of the one
  // its evidence was seen along (to the code's step, 1.4°).
  bool along_sight(std::size_t sl, double dx, double dy, double within) const;
  // Whether the global cell (gx, gy) is inside the window.
  bool contains(int gx, int gy) const { return gx - ox_ >= 0 && gx - ox_ < s_.side && gy - oy_ >= 0 && gy - oy_ < s_.side; }
  // The storage slot of global cell (gx, gy) (toroidal: the window's cells are a mask away).
  std::size_t slot(int gx, int gy) const { return static_cast<std::size_t>((gy & mask_) * s_.side + (gx & mask_)); }
  Cell& at(int gx, int gy) { return cells_[slot(gx, gy)]; }
  const Cell& at(int gx, int gy) const { return cells_[slot(gx, gy)]; }
  int index(double v) const;  // global cell index of a coordinate
  // Clears the cells of global column gx (every row of the window) / row gy.
  void clear_column(int gx);
  void clear_row(int gy);

  // A cell of evidence carried into the current frame: where it was observed, exactly.
  struct Carried {
    Eigen::Vector2d centre;  // the observed cell's centre, carried into the current frame, m
    double turn;             // rotation from the frame it was observed in to the current one, rad
    std::uint64_t tick;      // its evidence tick
    std::uint8_t sight;      // the line of sight it was seen along, in the current frame (sight_code)
  };
  // Calls visit(gx, gy) for each window cell of the box holding a carried cell's turned square
  // (its half side: half a cell × (|cos turn| + |sin turn|)); stops early when visit returns true.
  template <class Visit>
  bool for_box(const Carried& c, Visit visit) const;
  // Whether some cell of a carried cell's box still holds the evidence carry() put there.
  bool still_there(const Carried& c) const;
  // Adds to next_ the carried cells still there (carried) or the observed evidence cells
  // (!carried) within (near) or beyond (!near) `radius` of `robot` (old frame, m), up to kCarried.
  void collect(const Eigen::Vector2d& robot, double radius, bool near, bool carried);
  // Clears every cell and flag (reset() also forgets the carried cells and the placement).
  void clear_cells();
  GridSettings s_;
  std::vector<Carried> carried_;         // evidence in the grid that carry() put there, kCarried reserved
  std::vector<Carried> next_;            // scratch of carry(), kCarried reserved at construction
  static constexpr std::uint8_t kFromCarry = 1;  // flag: the cell's evidence came from carry()
  static constexpr std::uint8_t kSoft = 2;       // flag: the cell's evidence is only explained arcs' (mark_arc)
  static constexpr std::uint8_t kSingle = 4;     // flag: one echo's evidence, not marked again since (mark_arc)
  std::vector<std::uint8_t> flags_;              // per slot: kFromCarry, kSoft, kSingle
  std::vector<std::uint8_t> sight_;              // per slot: the line of sight of its last echo (sight_code)
  int mask_ = 255;           // side − 1
  std::vector<Cell> cells_;  // side² cells, slot (gx mod side, gy mod side)
  int ox_ = 0;               // global index of the window's first column
  int oy_ = 0;               // global index of the window's first row
  bool placed_ = false;      // the window has been placed around a robot
  KnownStructure* known_ = nullptr;  // the a-priori map's structure, or none
  std::uint64_t narrowed_cells_ = 0;      // arc cells left unmarked by narrowing, count
  std::uint64_t unexplained_echoes_ = 0;  // echoes whose every arc point was ruled out (marked whole), count
};

}  // namespace robuter::emergency

// SPDX-License-Identifier: GPL-3.0-or-later
// The evidence grid: free-space certificates of each reading's cone, obstacle evidence on its echo arc.
#include "modules/emergency/evidence_grid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <numbers>

namespace robuter::emergency {

namespace {
// The smallest power of two not below n (the window's side, so slots are a mask away).
int power_of_two(int n) {
  int p = 1;
  while (p < n) p <<= 1;
  return p;
}
}  // namespace

EvidenceGrid::EvidenceGrid(const GridSettings& s) : s_(s) {
  s_.side = power_of_two(std::max(s_.side, 8));
  mask_ = s_.side - 1;
  cells_.assign(static_cast<std::size_t>(s_.side) * static_cast<std::size_t>(s_.side), Cell{});
  flags_.assign(cells_.size(), 0);
  sight_.assign(cells_.size(), 0);
  carried_.reserve(kCarried);
  next_.reserve(kCarried);
}

template <class Visit>
bool EvidenceGrid::for_box(const Carried& c, Visit visit) const {
  const double ext = 0.5 * s_.cell * (std::abs(std::cos(c.turn)) + std::abs(std::sin(c.turn)));
  const int x0 = index(c.centre.x() - ext), x1 = index(c.centre.x() + ext);
  const int y0 = index(c.centre.y() - ext), y1 = index(c.centre.y() + ext);
  for (int gy = y0; gy <= y1; ++gy)
    for (int gx = x0; gx <= x1; ++gx)
      if (contains(gx, gy) && visit(gx, gy)) return true;
  return false;
}

bool EvidenceGrid::still_there(const Carried& c) const {
  return for_box(c, [&](int gx, int gy) {
    const Cell& cell = at(gx, gy);
    return (flags_[slot(gx, gy)] & kFromCarry) != 0 && cell.hit_tick != 0 && cell.hit_tick >= cell.free_tick;
  });
}

void EvidenceGrid::collect(const Eigen::Vector2d& robot, double radius, bool near, bool carried) {
  const double r2 = radius * radius;
  if (carried) {
    for (const Carried& c : carried_) {
      if (((c.centre - robot).squaredNorm() <= r2) != near || !still_there(c)) continue;
      if (next_.size() == kCarried) return;
      next_.push_back(c);
    }
    return;
  }
  for (int gy = oy_; gy < oy_ + s_.side; ++gy) {
    for (int gx = ox_; gx < ox_ + s_.side; ++gx) {
      const Cell& cell = at(gx, gy);
      if (cell.hit_tick == 0 || cell.hit_tick < cell.free_tick) continue;
      if ((flags_[slot(gx, gy)] & kFromCarry) != 0) continue;  // in carried_
      const Eigen::Vector2d c((gx + 0.5) * s_.cell, (gy + 0.5) * s_.cell);
      if (((c - robot).squaredNorm() <= r2) != near) continue;
      if (next_.size() == kCarried) return;
      next_.push_back({c, 0.0, cell.hit_tick, sight_[slot(gx, gy)]});
    }
  }
}

// Seeds 2602, 3145, 3758, 3776, 3930, 4788, 6381 and 6777 of the 10,000 random sequences: after
// an AC the grid used to be reset, a box the robot had seen come within the blanking range was
// forgotten, and the start pose's creep touched it. EvidenceGrid.ManyOdometrySetsAtRest…: carrying
// the marked boxes themselves widened the evidence by a cell per frame (80 frames at rest: 2.5 m²
// of phantom evidence round the robot); carried cells now keep where they were observed.
void EvidenceGrid::carry(const Eigen::Matrix2d& rotation, const Eigen::Vector2d& translation,
                         const Eigen::Vector2d& robot) {
  next_.clear();
  if (placed_) {
    // The robot in the old frame: where the new frame's robot came from.
    const Eigen::Vector2d old_robot = rotation.transpose() * (robot - translation);
    collect(old_robot, 1.0, true, true);
    collect(old_robot, 1.0, true, false);
    collect(old_robot, 1.0, false, true);
    collect(old_robot, 1.0, false, false);
  }
  clear_cells();
  placed_ = false;
  follow(robot);
  // The observed cell's square, turned, lies inside the box of its turned corners: every new cell
  // of that box is marked (2 × 2 cells for a translation, 3 × 3 at most for a turn).
  const double turn = std::atan2(rotation(1, 0), rotation(0, 0));
  carried_.clear();
  for (Carried c : next_) {
    c.centre = rotation * c.centre + translation;
    c.turn += turn;
    c.sight = static_cast<std::uint8_t>(c.sight + sight_code(turn));  // the line of sight turns with the frame
    for_box(c, [&](int gx, int gy) {
      Cell& cell = cells_[slot(gx, gy)];
      cell.hit_tick = std::max(cell.hit_tick, c.tick);
      flags_[slot(gx, gy)] = kFromCarry;  // carried evidence is never soft
      sight_[slot(gx, gy)] = c.sight;
      return false;
    });
    carried_.push_back(c);
  }
  next_.clear();
}

// A direction in 256 steps of a turn.
constexpr double kSightStep = 2.0 * std::numbers::pi / 256.0;  // rad

std::uint8_t EvidenceGrid::sight_code(double angle) {
  return static_cast<std::uint8_t>(static_cast<int>(std::lround(angle / kSightStep)) & 255);
}

bool EvidenceGrid::along_sight(std::size_t sl, double dx, double dy, double within) const {
  // The difference of two codes, as a signed step count in [-128, 127].
  const auto diff = static_cast<std::int8_t>(static_cast<std::uint8_t>(sight_code(std::atan2(dy, dx)) - sight_[sl]));
  return std::abs(static_cast<int>(diff)) * kSightStep <= within;
}

void EvidenceGrid::reset() {
  clear_cells();
  carried_.clear();
  placed_ = false;
}

void EvidenceGrid::clear_cells() {
  std::fill(cells_.begin(), cells_.end(), Cell{});
  std::fill(flags_.begin(), flags_.end(), std::uint8_t{0});
}

int EvidenceGrid::index(double v) const { return static_cast<int>(std::floor(v / s_.cell)); }

void EvidenceGrid::clear_column(int gx) {
  const int x = gx & mask_;
  for (int y = 0; y < s_.side; ++y) {
    cells_[static_cast<std::size_t>(y * s_.side + x)] = Cell{};
    flags_[static_cast<std::size_t>(y * s_.side + x)] = 0;
  }
}

void EvidenceGrid::clear_row(int gy) {
  const int y = gy & mask_;
  std::fill_n(cells_.begin() + static_cast<std::ptrdiff_t>(y * s_.side), s_.side, Cell{});
  std::fill_n(flags_.begin() + static_cast<std::ptrdiff_t>(y * s_.side), s_.side, std::uint8_t{0});
}

// Cells leaving the window are cleared: what was known there is forgotten, never misplaced.
void EvidenceGrid::follow(const Eigen::Vector2d& robot) {
  const int half = s_.side / 2;
  const int rx = index(robot.x()), ry = index(robot.y());
  if (!placed_) {
    ox_ = rx - half;
    oy_ = ry - half;
    placed_ = true;
    return;
  }
  if (std::abs(rx - (ox_ + half)) > s_.recentre_cells || std::abs(ry - (oy_ + half)) > s_.recentre_cells) {
    const int nx = rx - half, ny = ry - half;
    if (std::abs(nx - ox_) >= s_.side || std::abs(ny - oy_) >= s_.side) {
      reset();
      ox_ = nx;
      oy_ = ny;
      placed_ = true;
      return;
    }
    for (int gx = std::min(ox_, nx); gx < std::max(ox_, nx); ++gx) clear_column(gx < nx ? gx : gx + s_.side);
    for (int gy = std::min(oy_, ny); gy < std::max(oy_, ny); ++gy) clear_row(gy < ny ? gy : gy + s_.side);
    ox_ = nx;
    oy_ = ny;
  }
}

// Free space is certified only for cells wholly between the blanking range and the echo (less the
// range noise allowance), with their centre inside the cone; the arc is sampled at half a cell.
void EvidenceGrid::add_reading(std::uint64_t tick, const Eigen::Vector2d& origin, double direction, double range,
                               bool no_echo, bool contradicts) {
  certify_cone(tick, origin, direction, range, no_echo, contradicts);
  mark_arc(tick, origin, direction, range, no_echo);
}

void EvidenceGrid::certify_cone(std::uint64_t tick, const Eigen::Vector2d& origin, double direction, double range,
                                bool no_echo, bool contradicts) {
  if (!placed_ || tick == 0) return;
  const double half_diag = s_.cell * 0.7071067811865476;
  const double c = std::cos(direction), sn = std::sin(direction);
  const double ch = std::cos(s_.half_angle), sh = std::sin(s_.half_angle);
  const double r_in = s_.blanking + half_diag;
  const double r_out = std::min(range - (no_echo ? 0.0 : s_.shrink), s_.reach) - half_diag;
  if (r_out > r_in) {
    // Bounding box of the sector: apex, both edge ends, and the arc's axis extremes inside the cone.
    Eigen::Vector2d lo = origin, hi = origin;
    auto add = [&](double ux, double uy) {
      const Eigen::Vector2d p = origin + r_out * Eigen::Vector2d(ux, uy);
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    };
    add(c * ch + sn * sh, sn * ch - c * sh);
    add(c * ch - sn * sh, sn * ch + c * sh);
    if (c >= ch) add(1.0, 0.0);
    if (-c >= ch) add(-1.0, 0.0);
    if (sn >= ch) add(0.0, 1.0);
    if (-sn >= ch) add(0.0, -1.0);
    const int x0 = std::max(index(lo.x()), ox_), x1 = std::min(index(hi.x()), ox_ + s_.side - 1);
    const int y0 = std::max(index(lo.y()), oy_), y1 = std::min(index(hi.y()), oy_ + s_.side - 1);
    const double rin2 = r_in * r_in, rout2 = r_out * r_out;
    // The cosine's bound of "well inside the cone": half_angle - contradict_sight off its axis.
    const double inner = std::cos(std::max(0.0, s_.half_angle - s_.contradict_sight));
    for (int gy = y0; gy <= y1; ++gy) {
      const double dy = (gy + 0.5) * s_.cell - origin.y();
      for (int gx = x0; gx <= x1; ++gx) {
        const double dx = (gx + 0.5) * s_.cell - origin.x();
        const double r2 = dx * dx + dy * dy;
        if (r2 < rin2 || r2 > rout2) continue;
        const double along = dx * c + dy * sn;
        if (along <= 0.0 || along * along < r2 * ch * ch) continue;  // outside the cone
        Cell& cell = at(gx, gy);
        const bool evidence = cell.hit_tick != 0 && cell.hit_tick >= cell.free_tick;
        if (evidence) {
          // An echo from farther away clears evidence seen along nearly its own line of sight,
          // well inside its cone (a longer echo along a line a reflector echoed along: it is
          // gone, or was never there); evidence seen from elsewhere, or at its cone's edge, only
          // once no echo has repeated it for sight_age — the beam may have glanced off that very
          // surface on to a farther one (multipath, docs/SAFETY.md §13). A no-echo clears
          // only soft evidence (an explained arc's, mark_arc), along nearly its line of sight;
          // ties of a tick go to the evidence.
          const std::size_t sl = slot(gx, gy);
          const bool old_evidence = s_.sight_age > 0 && tick > cell.hit_tick + s_.sight_age;
          const bool clears = contradicts ? old_evidence ||
                                                (inner * inner * r2 <= along * along &&
                                                 along_sight(sl, dx, dy, s_.contradict_sight))
                                          : (flags_[sl] & kSoft) != 0 && cell.hit_tick < tick &&
                                                along_sight(sl, dx, dy, s_.narrow_sight);
          if (!clears) continue;
        }
        cell.free_tick = tick;
      }
    }
  }
}

bool EvidenceGrid::sees_through(const SeenCone& c, const Eigen::Vector2d& p, const Eigen::Vector2d& from,
                                std::uint64_t tick) const {
  if (c.tick == 0 || (c.tick < tick && tick - c.tick > s_.narrow_age)) return false;
  const Eigen::Vector2d d = p - c.origin;
  const double r2 = d.squaredNorm();
  const double r_out = std::min(c.range - s_.shrink, s_.reach);
  if (r2 <= s_.blanking * s_.blanking || r_out <= 0.0 || r2 >= r_out * r_out) return false;
  // Inside the cone; its edge counts as inside (an arc's end samples lie on it): 1e-9 of slack.
  const double along = d.x() * std::cos(c.direction) + d.y() * std::sin(c.direction);
  const double ch = std::cos(s_.half_angle);
  if (along <= 0.0 || along * along < r2 * ch * ch * (1.0 - 1e-9)) return false;
  // Within narrow_sight of the echo's line of sight.
  const Eigen::Vector2d e = p - from;
  const double cs = std::cos(s_.narrow_sight);
  const double dot = d.dot(e);
  return dot > 0.0 && dot * dot >= r2 * e.squaredNorm() * cs * cs;
}

// The echo came from somewhere on the arc at `range`: every cell of the arc that holds a point not
// ruled out becomes evidence. Narrowing needs an explanation first: known structure (the
// a-priori map) on the arc — the reflector may be there. Then a point off the structure is ruled
// out where a recent cone with an echo saw through it along nearly the same line of sight. A cone
// alone proves nothing: a face may echo to one transducer and be too oblique for its neighbour
// (the simulator's 40°; the random sequences found seeds 6604 and 9853 touching a box when cones
// alone narrowed arcs). A no-echo rules nothing out (a lost echo). Unexplained, the whole arc.
void EvidenceGrid::mark_arc(std::uint64_t tick, const Eigen::Vector2d& origin, double direction, double range,
                            bool no_echo, std::span<const SeenCone> seen) {
  if (!placed_ || tick == 0 || no_echo || range > s_.reach) return;
  // The cones that may reach the arc at all: the arc lies within rho of its middle point.
  std::array<const SeenCone*, kMaxSeen> near{};
  std::size_t near_count = 0;
  const bool narrowing = s_.narrow_age > 0 && known_ != nullptr;
  if (narrowing) {
    const Eigen::Vector2d mid = origin + range * Eigen::Vector2d(std::cos(direction), std::sin(direction));
    const double rho = range * std::sin(s_.half_angle) + s_.cell;
    for (const SeenCone& c : seen) {
      if (near_count == kMaxSeen) break;
      if (c.tick == 0 || (c.tick < tick && tick - c.tick > s_.narrow_age)) continue;
      const double d = (mid - c.origin).norm();
      if (d - rho >= c.range - s_.shrink || d + rho <= s_.blanking) continue;
      near[near_count++] = &c;
    }
  }
  std::array<std::uint32_t, kArcCells> arc;        // slots of the arc's cells, in order, without repeats
  std::array<std::uint8_t, kArcCells> possible{};  // some point of the cell on the arc is not ruled out
  std::array<std::uint8_t, kArcCells> on_structure{};  // some point of the cell on the arc is on known structure
  std::array<std::uint8_t, kArcCells> sight{};         // the line of sight to the cell (sight_code)
  int cells = 0;
  bool explained = false;
  const int n = std::max(2, static_cast<int>(std::ceil(2.0 * s_.half_angle * range / (0.5 * s_.cell)))) + 1;
  for (int i = 0; i < n; ++i) {
    const double a = direction - s_.half_angle + 2.0 * s_.half_angle * i / (n - 1);
    const Eigen::Vector2d p = origin + range * Eigen::Vector2d(std::cos(a), std::sin(a));
    const int gx = index(p.x()), gy = index(p.y());
    // The structure explains the echo wherever the arc meets it, inside the window or not (an
    // echo off a wall at the cone's edge, 2.5 m away, meets it just outside).
    const bool structure = narrowing && known_->occupied(p);
    explained = explained || structure;
    if (!contains(gx, gy)) continue;
    const auto sl = static_cast<std::uint32_t>(slot(gx, gy));
    if (cells == 0 || arc[static_cast<std::size_t>(cells - 1)] != sl) {
      if (cells == kArcCells) break;
      arc[static_cast<std::size_t>(cells)] = sl;
      // The line of sight to the cell's centre (the one certify_cone's test takes).
      sight[static_cast<std::size_t>(cells++)] =
          sight_code(std::atan2((gy + 0.5) * s_.cell - origin.y(), (gx + 0.5) * s_.cell - origin.x()));
    }
    if (!narrowing) continue;
    if (structure) on_structure[static_cast<std::size_t>(cells - 1)] = 1;
    bool out = !structure;
    if (out) {
      out = false;
      for (std::size_t k = 0; !out && k < near_count; ++k) out = sees_through(*near[k], p, origin, tick);
    }
    if (!out) possible[static_cast<std::size_t>(cells - 1)] = 1;
  }
  if (narrowing && !explained && cells > 0) ++unexplained_echoes_;
  for (int i = 0; i < cells; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (explained && possible[k] == 0) {
      ++narrowed_cells_;
      continue;
    }
    // Soft: a point of an explained arc off the structure that nothing ruled out; a later
    // certificate along nearly the same line of sight clears it, even a no-echo's. Hard
    // evidence stays hard.
    Cell& cell = cells_[arc[k]];
    const bool evidence_before = cell.hit_tick != 0 && cell.hit_tick >= cell.free_tick;
    const bool hard_before = evidence_before && (flags_[arc[k]] & kSoft) == 0;
    const bool soft = explained && on_structure[k] == 0 && !hard_before;
    cell.hit_tick = tick;
    // Observed here. Evidence a second echo marks (or carried evidence) is confirmed: never single.
    flags_[arc[k]] = static_cast<std::uint8_t>((soft ? kSoft : 0) | (evidence_before ? 0 : kSingle));
    sight_[arc[k]] = sight[k];
  }
}

// A cell is wholly inside the rectangle when its centre is half a diagonal inside every side.
void EvidenceGrid::certify_rectangle(std::uint64_t tick, const Eigen::Vector2d& position, double heading,
                                     const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) {
  if (!placed_ || tick == 0) return;
  const double half_diag = s_.cell * 0.7071067811865476;
  const Eigen::Vector2d in_lo = lo + Eigen::Vector2d::Constant(half_diag);
  const Eigen::Vector2d in_hi = hi - Eigen::Vector2d::Constant(half_diag);
  if (in_lo.x() > in_hi.x() || in_lo.y() > in_hi.y()) return;
  const double c = std::cos(heading), sn = std::sin(heading);
  Eigen::Vector2d wlo = position, whi = position;
  for (const Eigen::Vector2d& k : {Eigen::Vector2d(lo.x(), lo.y()), Eigen::Vector2d(lo.x(), hi.y()),
                                   Eigen::Vector2d(hi.x(), lo.y()), Eigen::Vector2d(hi.x(), hi.y())}) {
    const Eigen::Vector2d w = position + Eigen::Vector2d(c * k.x() - sn * k.y(), sn * k.x() + c * k.y());
    wlo = wlo.cwiseMin(w);
    whi = whi.cwiseMax(w);
  }
  const int x0 = std::max(index(wlo.x()), ox_), x1 = std::min(index(whi.x()), ox_ + s_.side - 1);
  const int y0 = std::max(index(wlo.y()), oy_), y1 = std::min(index(whi.y()), oy_ + s_.side - 1);
  for (int gy = y0; gy <= y1; ++gy) {
    const double dy = (gy + 0.5) * s_.cell - position.y();
    for (int gx = x0; gx <= x1; ++gx) {
      const double dx = (gx + 0.5) * s_.cell - position.x();
      const double lx = c * dx + sn * dy, ly = -sn * dx + c * dy;
      if (lx < in_lo.x() || lx > in_hi.x() || ly < in_lo.y() || ly > in_hi.y()) continue;
      at(gx, gy).free_tick = tick;
    }
  }
}

std::uint64_t EvidenceGrid::evidence_tick(const Eigen::Vector2d& p) const {
  const int gx = index(p.x()), gy = index(p.y());
  return placed_ && contains(gx, gy) ? at(gx, gy).hit_tick : 0;
}

CellState EvidenceGrid::state(const Eigen::Vector2d& p, std::uint64_t tick, std::uint64_t max_age) const {
  const int gx = index(p.x()), gy = index(p.y());
  if (!placed_ || !contains(gx, gy)) return CellState::unknown;
  const Cell& cell = at(gx, gy);
  if (cell.hit_tick != 0 && cell.hit_tick >= cell.free_tick) {
    // One echo's evidence that no later echo confirmed counts single_age ticks; then the cell is
    // what its certificates say (as a rule stale: no speed but a hold or the blind creep).
    const bool expired = s_.single_age > 0 && (flags_[slot(gx, gy)] & kSingle) != 0 && cell.hit_tick < tick &&
                         tick - cell.hit_tick > s_.single_age;
    if (!expired) return CellState::obstacle;
  }
  if (cell.free_tick == 0) return CellState::unknown;
  return tick - cell.free_tick <= max_age || cell.free_tick > tick ? CellState::free : CellState::stale;
}

}  // namespace robuter::emergency

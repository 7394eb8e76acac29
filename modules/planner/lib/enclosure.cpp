// SPDX-License-Identifier: GPL-3.0-or-later
// Is the robot shut in? A bit-parallel flood of the lean (cell, move slot) graph in a window.
#include "modules/planner/lib/enclosure.hpp"

#include <algorithm>
#include <bit>
#include <cstring>

#include "modules/planner/lib/pass_grid.hpp"

namespace robuter::plan {

namespace {

constexpr int kW = EnclosureTest::kWords;
constexpr int kN = EnclosureTest::kSize;

// Why: a window row (kW words, bit x of the row = cell x0 + x) moved by dx cells into `out`.
inline void shift_row(const std::uint64_t* v, int dx, std::uint64_t* out) {
  if (dx > 0) {
    for (int w = kW - 1; w >= 0; --w) out[w] = (v[w] << 1) | (w > 0 ? v[w - 1] >> 63 : 0);
  } else if (dx < 0) {
    for (int w = 0; w < kW; ++w) out[w] = (v[w] >> 1) | (w + 1 < kW ? v[w + 1] << 63 : 0);
  } else {
    for (int w = 0; w < kW; ++w) out[w] = v[w];
  }
}

// Why: a straight run along a row: every cell reachable from `gen` through cells of `pro`,
// towards higher x (dx > 0) or lower x (Kogge-Stone occluded fill per word, the run carried
// from word to word).
inline void fill_row(std::uint64_t* gen, const std::uint64_t* pro_row, int dx) {
  auto fill = [dx](std::uint64_t g, std::uint64_t p) {
    for (int d = 1; d < 64; d <<= 1) {
      if (dx > 0) {
        g |= p & (g << d);
        p &= p << d;
      } else {
        g |= p & (g >> d);
        p &= p >> d;
      }
    }
    return g;
  };
  if (dx > 0) {
    for (int w = 0; w < kW; ++w) {
      if (w > 0 && (gen[w - 1] >> 63) != 0) gen[w] |= pro_row[w] & 1u;
      gen[w] = fill(gen[w], pro_row[w]);
    }
  } else {
    for (int w = kW - 1; w >= 0; --w) {
      if (w + 1 < kW && (gen[w + 1] & 1u) != 0) gen[w] |= pro_row[w] & (std::uint64_t{1} << 63);
      gen[w] = fill(gen[w], pro_row[w]);
    }
  }
}

// Why: the window row's bits from one byte per cell (bit x set where byte x is nonzero; bytes
// hold 0, 1 or 2: a cell class, or a 0/1 flag): eight cells per multiply (their low bits
// gathered into one byte), so a row costs kN / 8 steps, not kN.
inline void pack_row(const std::uint8_t* bytes, std::uint64_t* out) {
  for (int w = 0; w < kW; ++w) {
    std::uint64_t word = 0;
    for (int b = 0; b < 64; b += 8) {
      std::uint64_t t;
      std::memcpy(&t, bytes + w * 64 + b, sizeof t);  // byte i in bits 8i.. (little endian)
      t = (t | (t >> 1)) & 0x0101010101010101ULL;
      word |= ((t * 0x0102040810204080ULL) >> 56) << b;
    }
    out[w] = word;
  }
}

inline void set_bit(std::uint64_t* row, int x, bool on) {
  const std::uint64_t b = std::uint64_t{1} << (x & 63);
  row[x >> 6] = on ? (row[x >> 6] | b) : (row[x >> 6] & ~b);
}
inline bool get_bit(const std::uint64_t* row, int x) { return ((row[x >> 6] >> (x & 63)) & 1u) != 0; }

// Why: row y of a slot's window bits.
template <class R>
auto row_of(R& r, int y) { return r.data() + static_cast<std::size_t>(y) * kW; }

}  // namespace

void EnclosureTest::reserve(int slots) {
  const auto n = static_cast<std::size_t>(std::max(slots, 1));
  if (free_.size() < n) {
    free_.resize(n);
    turn_.resize(n);
    seen_.resize(n);
  }
}

bool EnclosureTest::enclosed(const LeanGraph& g, int x0, int y0) {
  if (g.slots <= 0 || static_cast<std::size_t>(g.slots) > free_.size()) return false;
  const auto stride = static_cast<std::uint32_t>(g.stride);
  const int sx = static_cast<int>(g.start % stride) - x0;
  const int sy = static_cast<int>(g.start / stride) - y0;
  if (sx < 1 || sy < 1 || sx >= kN - 1 || sy >= kN - 1) return false;  // the start on the ring
  const Window w{x0, y0, std::max(x0, 0), std::min(x0 + kN, g.stride), std::max(y0, 0), std::min(y0 + kN, g.rows)};
  pack_free(g, w);
  if (g.slots > 1) pack_turns(g, w, sx, sy);
  seed(g, sx, sy);
  return flood(g, static_cast<int>(g.goal % stride) - x0, static_cast<int>(g.goal / stride) - y0);
}

void EnclosureTest::pack_free(const LeanGraph& g, const Window& w) {
  std::uint8_t cells[kN];  // one window row, a byte per cell (0 outside the map)
  std::memset(cells, 0, sizeof cells);
  for (int s = 0; s < g.slots; ++s) {
    const std::uint8_t* cls = g.cls_of[g.move_slice[s]];
    Rows& f = free_[static_cast<std::size_t>(s)];
    f.fill(0);
    for (int y = w.ya; y < w.yb; ++y) {
      std::memcpy(cells + (w.xa - w.x0), cls + static_cast<std::size_t>(y) * static_cast<std::size_t>(g.stride) +
                                             static_cast<std::size_t>(w.xa),
                  static_cast<std::size_t>(w.xb - w.xa));
      pack_row(cells, row_of(f, y - w.y0));
    }
  }
}

// Turns between slot s and s + 1 (the up arc from s): allowed where every slice of the arc is
// clear of the grown body (the search also asks the body itself clear: a superset here), or by
// the body's own rule where no turn room is kept; at the start cell, the body's own room (as the
// search).
void EnclosureTest::pack_turns(const LeanGraph& g, const Window& w, int sx, int sy) {
  std::uint8_t cells[kN];
  std::memset(cells, 0, sizeof cells);
  const bool grown = g.turn_bits != nullptr;
  for (int s = 0; s < g.slots; ++s) {
    const int ka = g.move_slice[s];
    const int steps = (g.move_slice[(s + 1) % g.slots] - ka + g.slices) % g.slices;
    std::uint32_t arc[4] = {0, 0, 0, 0};  // the arc's slices as turn bits (up to 128 slices)
    for (int q = 0, j = ka; q <= steps; ++q, j = (j + 1) % g.slices)
      if ((j >> 5) < 4) arc[j >> 5] |= std::uint32_t{1} << (j & 31);
    Rows& t = turn_[static_cast<std::size_t>(s)];
    t.fill(0);
    for (int y = w.ya; y < w.yb; ++y) {
      const std::uint32_t row0 = static_cast<std::uint32_t>(y) * static_cast<std::uint32_t>(g.stride);
      if (grown && g.turn_words == 1) {  // the default (up to 32 slices): one word per cell, a loop that vectorises
        const std::uint32_t* wb = g.turn_bits + row0;
        for (int x = w.xa; x < w.xb; ++x) cells[x - w.x0] = (wb[x] & arc[0]) == 0 ? 1 : 0;
        pack_row(cells, row_of(t, y - w.y0));
        continue;
      }
      for (int x = w.xa; x < w.xb; ++x) {
        const std::uint32_t cell = row0 + static_cast<std::uint32_t>(x);
        bool ok = true;
        if (grown && g.turn_words <= 4) {
          const std::uint32_t* wb = g.turn_bits + static_cast<std::size_t>(cell) * static_cast<std::size_t>(g.turn_words);
          for (int k = 0; k < g.turn_words; ++k) ok = ok && (wb[k] & arc[k]) == 0;
        } else {  // the body's rule: a superset of the grown body's where more slices are kept
          ok = arc_free(g, false, cell, ka, steps, +1);
        }
        cells[x - w.x0] = ok ? 1 : 0;
      }
      pack_row(cells, row_of(t, y - w.y0));
    }
    set_bit(row_of(t, sy), sx, arc_free(g, false, g.start, ka, steps, +1));
  }
}

// Seeds: the start slot, or from a pass-through start slice the nearest move slots either way
// that the body's own room lets the robot turn to.
void EnclosureTest::seed(const LeanGraph& g, int sx, int sy) {
  for (int s = 0; s < g.slots; ++s) seen_[static_cast<std::size_t>(s)].fill(0);
  const int s0 = g.start_slice;
  if (g.slot_of[s0] >= 0) {
    set_bit(row_of(seen_[static_cast<std::size_t>(g.slot_of[s0])], sy), sx, true);
  } else {
    for (int dir = -1; dir <= 1; dir += 2) {
      int steps = 0;
      const int j = next_move_slice(g, s0, dir, steps);
      if (arc_free(g, false, g.start, s0, steps, dir))
        set_bit(row_of(seen_[static_cast<std::size_t>(g.slot_of[j])], sy), sx, true);
    }
  }
  for (int s = 0; s < g.slots; ++s)
    for (int k = 0; k < kW; ++k)
      row_of(seen_[static_cast<std::size_t>(s)], sy)[k] &= row_of(free_[static_cast<std::size_t>(s)], sy)[k];
}

bool EnclosureTest::flood(const LeanGraph& g, int gx, int gy) {
  const bool goal_inside = gx >= 0 && gy >= 0 && gx < kN && gy < kN;
  std::uint64_t count = ~std::uint64_t{0};
  std::uint64_t tmp[kW];
  for (;;) {
    // Straight runs within each slot, one sweep per allowed direction.
    for (int s = 0; s < g.slots; ++s) {
      Rows& f = free_[static_cast<std::size_t>(s)];
      Rows& v = seen_[static_cast<std::size_t>(s)];
      const std::uint8_t bits = g.allowed[g.move_slice[s]];
      for (int m = 0; m < 8; ++m) {
        if (!(bits & (1u << m))) continue;
        const int dx = kMoveDx[static_cast<std::size_t>(m)];
        const int dy = kMoveDy[static_cast<std::size_t>(m)];
        if (dy == 0) {
          for (int r = 0; r < kN; ++r) fill_row(row_of(v, r), row_of(f, r), dx);
          continue;
        }
        for (int r = dy > 0 ? 0 : kN - 1; r != (dy > 0 ? kN - 1 : 0); r += dy) {
          const std::uint64_t* fv = row_of(f, r + dy);
          std::uint64_t src[kW];
          for (int k = 0; k < kW; ++k) src[k] = row_of(v, r)[k];
          if (dx != 0) {  // a diagonal: both side cells free, no corner cutting
            shift_row(row_of(f, r), -dx, tmp);
            for (int k = 0; k < kW; ++k) src[k] &= tmp[k] & fv[k];
          }
          shift_row(src, dx, tmp);
          std::uint64_t* vv = row_of(v, r + dy);
          for (int k = 0; k < kW; ++k) vv[k] |= tmp[k] & fv[k];
        }
      }
    }
    // Turns in place between neighbouring slots, both ways.
    for (int s = 0; g.slots > 1 && s < g.slots; ++s) {
      const auto a = static_cast<std::size_t>(s);
      const auto b = static_cast<std::size_t>((s + 1) % g.slots);
      const Rows& t = turn_[a];
      for (std::size_t i = 0; i < t.size(); ++i) {
        seen_[b][i] |= seen_[a][i] & t[i] & free_[b][i];
        seen_[a][i] |= seen_[b][i] & t[i] & free_[a][i];
      }
    }
    // Out through the ring, or at the goal: not shut in. Else stop when nothing was added.
    std::uint64_t n = 0;
    for (int s = 0; s < g.slots; ++s) {
      Rows& v = seen_[static_cast<std::size_t>(s)];
      for (int k = 0; k < kW; ++k)
        if (row_of(v, 0)[k] != 0 || row_of(v, kN - 1)[k] != 0) return false;
      if (goal_inside && get_bit(row_of(v, gy), gx)) return false;
      for (int r = 0; r < kN; ++r) {
        const std::uint64_t* row = row_of(v, r);
        if ((row[0] & 1u) != 0 || (row[kW - 1] >> 63) != 0) return false;
        for (int k = 0; k < kW; ++k) n += static_cast<std::uint64_t>(std::popcount(row[k]));
      }
    }
    if (n == count) return true;
    count = n;
  }
}

}  // namespace robuter::plan

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

// Why: is every slice of the arc from `from` by `steps` steps in direction `dir` clear of the
// body at a stored cell (the start cell's turn rule: the body's own room)?
bool body_arc_free(const LeanGraph& g, std::uint32_t cell, int from, int steps, int dir) {
  int j = from;
  if (g.cls_of[j][cell] == kBlocked) return false;
  for (int q = 0; q < steps; ++q) {
    j = (j + dir + g.slices) % g.slices;
    if (g.cls_of[j][cell] == kBlocked) return false;
  }
  return true;
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
  sweeps_ = 0;
  const int slots = g.slots;
  if (slots <= 0 || static_cast<std::size_t>(slots) > free_.size()) return false;
  const auto stride = static_cast<std::uint32_t>(g.stride);
  const int sx = static_cast<int>(g.start % stride) - x0;
  const int sy = static_cast<int>(g.start / stride) - y0;
  if (sx < 1 || sy < 1 || sx >= kN - 1 || sy >= kN - 1) return false;  // the start on the ring
  const int xa = std::max(x0, 0);
  const int xb = std::min(x0 + kN, g.stride);  // stored columns [xa, xb) lie in the window
  const int ya = std::max(y0, 0);
  const int yb = std::min(y0 + kN, g.rows);    // stored rows [ya, yb)
  auto row_of = [](Rows& r, int y) { return r.data() + static_cast<std::size_t>(y) * kW; };

  // The window's free states per slot.
  std::uint8_t cells[kN];  // one window row, a byte per cell (0 outside the map)
  std::memset(cells, 0, sizeof cells);
  for (int s = 0; s < slots; ++s) {
    const std::uint8_t* cls = g.cls_of[g.move_slice[s]];
    Rows& f = free_[static_cast<std::size_t>(s)];
    f.fill(0);
    for (int y = ya; y < yb; ++y) {
      std::memcpy(cells + (xa - x0), cls + static_cast<std::size_t>(y) * stride + static_cast<std::size_t>(xa),
                  static_cast<std::size_t>(xb - xa));
      pack_row(cells, row_of(f, y - y0));
    }
  }
  // Turns between slot s and s + 1 (the up arc from s): allowed where every slice of the arc is
  // clear of the grown body (the search also asks the body itself clear: a superset here), or of
  // the body where no turn room is kept; at the start cell, the body's own room (as the search).
  const bool grown = g.turn_room != nullptr && g.turn_room->slices == g.slices;
  if (slots > 1) {
    for (int s = 0; s < slots; ++s) {
      const int ka = g.move_slice[s];
      const int kb = g.move_slice[(s + 1) % slots];
      const int steps = (kb - ka + g.slices) % g.slices;
      Rows& t = turn_[static_cast<std::size_t>(s)];
      t.fill(0);
      const int words = grown ? g.turn_room->words : 0;
      std::uint32_t arc[4] = {0, 0, 0, 0};  // the arc's slices as turn-room bits (up to 128 slices)
      for (int q = 0, j = ka; q <= steps; ++q, j = (j + 1) % g.slices)
        if ((j >> 5) < 4) arc[j >> 5] |= std::uint32_t{1} << (j & 31);
      std::memset(cells, 0, sizeof cells);
      for (int y = ya; y < yb; ++y) {
        const std::uint32_t row0 = static_cast<std::uint32_t>(y) * stride;
        if (grown && words == 1) {  // the default: one word of bits per cell
          const std::uint32_t* wb = g.turn_room->bits.data() + row0;
          for (int x = xa; x < xb; ++x) cells[x - x0] = (wb[x] & arc[0]) == 0 ? 1 : 0;
        } else {
          for (int x = xa; x < xb; ++x) {
            const std::uint32_t cell = row0 + static_cast<std::uint32_t>(x);
            bool ok = true;
            if (grown && words <= 4) {
              const std::uint32_t* wb = g.turn_room->bits.data() + static_cast<std::size_t>(cell) * static_cast<std::size_t>(words);
              for (int w = 0; w < words; ++w) ok = ok && (wb[w] & arc[w]) == 0;
            } else {
              ok = body_arc_free(g, cell, ka, steps, +1);
            }
            cells[x - x0] = ok ? 1 : 0;
          }
        }
        pack_row(cells, row_of(t, y - y0));
      }
      set_bit(row_of(t, sy), sx, body_arc_free(g, g.start, ka, steps, +1));
    }
  }

  // Seeds: the start slot, or from a pass-through start slice the nearest move slots either way
  // that the body's own room lets the robot turn to.
  for (int s = 0; s < slots; ++s) seen_[static_cast<std::size_t>(s)].fill(0);
  const int s0 = g.start_slice;
  if (g.slot_of[s0] >= 0) {
    set_bit(row_of(seen_[static_cast<std::size_t>(g.slot_of[s0])], sy), sx, true);
  } else {
    for (int dir = -1; dir <= 1; dir += 2) {
      int j = s0;
      int steps = 0;
      do j = (j + dir + g.slices) % g.slices, ++steps;
      while (g.slot_of[j] < 0);
      if (body_arc_free(g, g.start, s0, steps, dir))
        set_bit(row_of(seen_[static_cast<std::size_t>(g.slot_of[j])], sy), sx, true);
    }
  }
  for (int s = 0; s < slots; ++s)
    for (int w = 0; w < kW; ++w)
      row_of(seen_[static_cast<std::size_t>(s)], sy)[w] &= row_of(free_[static_cast<std::size_t>(s)], sy)[w];

  const int gx = static_cast<int>(g.goal % stride) - x0;
  const int gy = static_cast<int>(g.goal / stride) - y0;
  const bool goal_inside = gx >= 0 && gy >= 0 && gx < kN && gy < kN;
  std::uint64_t count = ~std::uint64_t{0};
  std::uint64_t tmp[kW];
  for (;;) {
    ++sweeps_;
    // Straight runs within each slot, one sweep per allowed direction.
    for (int s = 0; s < slots; ++s) {
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
        const bool diag = dx != 0;
        for (int r = dy > 0 ? 0 : kN - 1; r != (dy > 0 ? kN - 1 : 0); r += dy) {
          const std::uint64_t* fu = row_of(f, r);
          const std::uint64_t* fv = row_of(f, r + dy);
          std::uint64_t src[kW];
          for (int w = 0; w < kW; ++w) src[w] = row_of(v, r)[w];
          if (diag) {  // both side cells free: no corner cutting
            shift_row(fu, -dx, tmp);
            for (int w = 0; w < kW; ++w) src[w] &= tmp[w] & fv[w];
          }
          shift_row(src, dx, tmp);
          std::uint64_t* vv = row_of(v, r + dy);
          for (int w = 0; w < kW; ++w) vv[w] |= tmp[w] & fv[w];
        }
      }
    }
    // Turns in place between neighbouring slots, both ways.
    if (slots > 1) {
      for (int s = 0; s < slots; ++s) {
        const auto a = static_cast<std::size_t>(s);
        const auto b = static_cast<std::size_t>((s + 1) % slots);
        const Rows& t = turn_[a];
        for (std::size_t i = 0; i < t.size(); ++i) {
          seen_[b][i] |= seen_[a][i] & t[i] & free_[b][i];
          seen_[a][i] |= seen_[b][i] & t[i] & free_[a][i];
        }
      }
    }
    // Out through the ring, or at the goal: not shut in. Else stop when nothing was added.
    std::uint64_t n = 0;
    for (int s = 0; s < slots; ++s) {
      Rows& v = seen_[static_cast<std::size_t>(s)];
      for (int w = 0; w < kW; ++w)
        if (row_of(v, 0)[w] != 0 || row_of(v, kN - 1)[w] != 0) return false;
      if (goal_inside && get_bit(row_of(v, gy), gx)) return false;
      for (int r = 0; r < kN; ++r) {
        const std::uint64_t* row = row_of(v, r);
        if ((row[0] & 1u) != 0 || (row[kW - 1] >> 63) != 0) return false;
        for (int w = 0; w < kW; ++w) n += static_cast<std::uint64_t>(std::popcount(row[w]));
      }
    }
    if (n == count) return true;
    count = n;
  }
}

}  // namespace robuter::plan

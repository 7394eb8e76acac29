// SPDX-License-Identifier: GPL-3.0-or-later
// KLD-sampling's count of occupied pose bins, in a fixed table (no allocation after construction).
#pragma once

#include <cstdint>
#include <vector>

namespace robuter::loc {

// The number of particles KLD-sampling asks for when the samples so far fill `bins` bins (Fox
// 2003): the Wilson-Hilferty approximation of the chi-square quantile, for error `epsilon` and
// standard normal upper quantile `z`.
double kld_needed(int bins, double epsilon, double z);

// An (x, y, theta) bin as one 64-bit key: 21 bits of each (two's complement), bit 63 clear.
// KldBins keys on it; the filter's promise cache too (particle_filter.cpp). unpack() reverses it.
inline std::uint64_t pack_bins(int bx, int by, int bt) {
  const auto pack = [](int v) { return static_cast<std::uint64_t>(static_cast<std::uint32_t>(v) & 0x1FFFFFu); };
  return (pack(bx) << 42) | (pack(by) << 21) | pack(bt);
}

// A set of (x, y, theta) bin keys with room for `capacity` distinct ones: open addressing over a
// table of twice the capacity, cleared in time proportional to what was inserted.
class KldBins {
 public:
  explicit KldBins(int capacity = 0);
  // Adds the bin; true when it was not there yet (false also when the table is full).
  bool insert(int bx, int by, int bt);
  // Counts one more in the bin (added if new and there is room); the bin's count after, 0 when full.
  int add(int bx, int by, int bt);
  // How many add() counted in the bin (0 when absent).
  int count(int bx, int by, int bt) const;
  int size() const { return size_; }
  void clear();
  // The bins, in the order they were first added or inserted: f(bx, by, bt, count).
  template <typename F>
  void for_each(F&& f) const {
    for (const auto i : used_) {
      const std::uint64_t k = keys_[i] - 1;
      f(unpack(k >> 42), unpack(k >> 21), unpack(k), counts_[i]);
    }
  }

 private:
  std::vector<std::uint64_t> keys_;  // 0 = empty slot; key = packed bin + 1
  std::vector<std::uint32_t> used_;  // slots filled since the last clear
  std::vector<int> counts_;          // per slot: what add() counted
  int size_ = 0;                     // distinct bins inserted
  int capacity_ = 0;                 // most bins kept

  // The slot holding the bin, or the empty slot where it would go.
  std::size_t slot(std::uint64_t key) const;
  static std::uint64_t key_of(int bx, int by, int bt);
  // One 21-bit field of a key back to its (signed) bin.
  static int unpack(std::uint64_t field) {
    const auto v = static_cast<std::int32_t>(field & 0x1FFFFFu);
    return v >= 0x100000 ? v - 0x200000 : v;
  }
};

}  // namespace robuter::loc

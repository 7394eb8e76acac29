// SPDX-License-Identifier: GPL-3.0-or-later
// A small seeded random generator (xoshiro256**) whose sequence is the same on every platform.
#pragma once

#include <cmath>
#include <cstdint>

namespace robuter::sim {

// Deterministic, allocation-free random numbers for noise models; the same seed gives the same
// run everywhere (std::normal_distribution is implementation-defined, this is not).
class Rng {
 public:
  explicit Rng(std::uint64_t seed = 1) { reseed(seed); }

  // Restarts the sequence from `seed` (expanded with splitmix64, as the xoshiro authors advise).
  void reseed(std::uint64_t seed) {
    for (auto& w : s_) {
      seed += 0x9E3779B97F4A7C15ULL;
      std::uint64_t z = seed;
      z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
      z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
      w = z ^ (z >> 31);
    }
    has_spare_ = false;
  }

  // Next raw 64-bit output.
  std::uint64_t next() {
    const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }

  // Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

  // Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

  // Standard normal (mean 0, deviation 1) by the polar Box-Muller method.
  double normal() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    double u, v, s;
    do {
      u = 2.0 * uniform() - 1.0;
      v = 2.0 * uniform() - 1.0;
      s = u * u + v * v;
    } while (s >= 1.0 || s == 0.0);
    const double m = std::sqrt(-2.0 * std::log(s) / s);
    spare_ = v * m;
    has_spare_ = true;
    return u * m;
  }

  // True with probability p.
  bool chance(double p) { return p > 0.0 && uniform() < p; }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

  std::uint64_t s_[4] = {};  // generator state
  double spare_ = 0.0;       // second normal deviate of the last Box-Muller pair
  bool has_spare_ = false;   // whether spare_ is unused
};

}  // namespace robuter::sim

// SPDX-License-Identifier: GPL-3.0-or-later
// KLD-sampling's bound and bin set (kld_bins.hpp).
#include "modules/localise/lib/kld_bins.hpp"

#include <cmath>

namespace robuter::loc {

double kld_needed(int bins, double epsilon, double z) {
  if (bins <= 1) return 1.0;
  const double k = bins - 1;
  const double a = 2.0 / (9.0 * k);
  const double c = 1.0 - a + std::sqrt(a) * z;
  return k / (2.0 * epsilon) * c * c * c;
}

KldBins::KldBins(int capacity)
    : keys_(static_cast<std::size_t>(capacity) * 2 + 1, 0), counts_(keys_.size(), 0), capacity_(capacity) {
  used_.reserve(static_cast<std::size_t>(capacity));
}

std::uint64_t KldBins::key_of(int bx, int by, int bt) {
  return pack_bins(bx, by, bt) + 1;
}

std::size_t KldBins::slot(std::uint64_t key) const {
  const std::uint64_t h = key * 0x9E3779B97F4A7C15ull;
  const std::size_t n = keys_.size();
  std::size_t i = static_cast<std::size_t>(h >> 20) % n;
  while (keys_[i] != key && keys_[i] != 0) i = i + 1 == n ? 0 : i + 1;
  return i;
}

bool KldBins::insert(int bx, int by, int bt) {
  if (size_ >= capacity_) return false;
  const std::uint64_t key = key_of(bx, by, bt);
  const std::size_t i = slot(key);
  if (keys_[i] == key) return false;
  keys_[i] = key;
  used_.push_back(static_cast<std::uint32_t>(i));
  ++size_;
  return true;
}

int KldBins::add(int bx, int by, int bt) {
  const std::uint64_t key = key_of(bx, by, bt);
  const std::size_t i = slot(key);
  if (keys_[i] != key) {
    if (size_ >= capacity_) return 0;
    keys_[i] = key;
    used_.push_back(static_cast<std::uint32_t>(i));
    ++size_;
  }
  return ++counts_[i];
}

int KldBins::count(int bx, int by, int bt) const {
  const std::uint64_t key = key_of(bx, by, bt);
  const std::size_t i = slot(key);
  return keys_[i] == key ? counts_[i] : 0;
}

void KldBins::clear() {
  for (const auto i : used_) {
    keys_[i] = 0;
    counts_[i] = 0;
  }
  used_.clear();
  size_ = 0;
}

}  // namespace robuter::loc
